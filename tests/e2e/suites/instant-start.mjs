// Instant start: <html data-numbers> (build → live, cached → live, stale while typing
// before Python is ready), the snapshot refused → full boot, no SharedWorker → dedicated Worker,
// embeds sharing one runtime per kind, and the server's compression and validators.
import { readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { watchWorkers } from '../workers.mjs';

/** A gate for the Python runtime's files: requests under pyodide/ wait until open() is called. */
function gate() {
  let open;
  const opened = new Promise((r) => (open = r));
  return { hold: (rel) => (rel.startsWith('pyodide/') ? opened : undefined), open: () => open() };
}
const numbersIs = (page, v, timeout = 60_000) =>
  page.waitForFunction((want) => document.documentElement.dataset.numbers === want, v, { timeout, polling: 20 });

export default async function instantStart(ctx) {
  const { check, assert, newPage, compareShown, golden, cpython, serve, browser, ROOT, SHOTS, valueOf } = ctx;
  const seed = golden('01_seed_motor.json');

  await check('data-numbers: "build" before Python (seed numbers, marked), typing kept and computed once ready, then "live"', async () => {
    const g = gate();
    const srv = await serve('/held/', { hold: g.hold });
    const page = await newPage();
    await page.goto(srv.url);
    await numbersIs(page, 'build', 15_000);
    const n = await compareShown(page, seed.expected);
    assert(n >= 60, `only ${n} prerendered numbers`);
    assert((await page.$eval('section.panel', (e) => getComputedStyle(e).borderTopStyle)) === 'dashed', 'build numbers not marked');
    assert((await page.$$('.status .prelive')).length === 1, 'status does not say where the numbers come from');
    // Through CDP: page.screenshot waits for web fonts, and while the held Pyodide requests (and
    // their boot retries) occupy HTTP/1.1's six connections, the KaTeX fonts wait behind them.
    const cdp = await page.context().newCDPSession(page);
    writeFileSync(join(SHOTS, '10-build-numbers.png'), Buffer.from((await cdp.send('Page.captureScreenshot')).data, 'base64'));
    await cdp.detach();
    await page.fill('input[name="motor.rs_ohm"]', '3.3');
    await numbersIs(page, 'stale', 5000);
    assert(await page.$eval('main.panels', (e) => e.classList.contains('stale')), 'panels not marked stale');
    const want = cpython({ ...seed.input, motor: { ...seed.input.motor, rs_ohm: 3.3 } });
    g.open();
    await numbersIs(page, 'live');
    assert((await page.inputValue('input[name="motor.rs_ohm"]')) === '3.3', 'typed value lost');
    assert(await compareShown(page, want) >= 60, 'live numbers');
    assert((await valueOf(page, 'vendor.Rpm.value')) === want.vendor.Rpm.value, 'Rpm of the typed input');

    // A returning visitor: the last report, kept locally, paints before Python ("cached").
    await page.waitForTimeout(1500); // the cache is written after a pause
    const state = await page.context().storageState();
    await page.context().close();
    const g2 = gate();
    const srv2 = await serve('/held/', { hold: g2.hold }); // same path, new origin (port): copy the storage over
    const origin = new URL(srv.url).origin;
    const st = { cookies: [], origins: state.origins.filter((o) => o.origin === origin).map((o) => ({ ...o, origin: new URL(srv2.url).origin })) };
    const c2 = await browser.newContext({ viewport: { width: 1366, height: 768 }, storageState: st });
    const p2 = await c2.newPage();
    p2.on('pageerror', (e) => { throw e; });
    await p2.goto(srv2.url);
    await numbersIs(p2, 'cached', 15_000);
    assert(await compareShown(p2, want) >= 60, 'cached numbers');
    g2.open();
    await numbersIs(p2, 'live');
    await c2.close();
  });

  await check('snapshot refused (404, or a wrong size) → Python boots in full, same golden numbers', async () => {
    for (const [prefix, faults] of [['/nosnap/', { refuse: /snapshot-.*\.bin/ }], ['/badsnap/', { corrupt: /snapshot-.*\.bin/ }]]) {
      const srv = await serve(prefix, faults);
      const page = await newPage();
      await page.goto(srv.url);
      await numbersIs(page, 'live', 90_000);
      const d = await page.evaluate(() => ({ ...document.documentElement.dataset }));
      assert(d.pythonBoot === 'full', `boot from ${d.pythonBoot}`);
      assert(await compareShown(page, seed.expected) >= 60, 'numbers');
      await page.context().close();
    }
    const dist = readdirSync(join(ROOT, 'dist/pyodide'));
    assert(dist.some((f) => /^snapshot-[0-9a-f]{12}\.bin$/.test(f)), 'the build made no snapshot (so the fast path was not tested)');
  });

  await check('the snapshot is used when served (data-python-boot="snapshot")', async () => {
    const page = await newPage();
    await page.goto(ctx.subSrv.url);
    await numbersIs(page, 'live', 60_000);
    assert((await page.evaluate(() => document.documentElement.dataset.pythonBoot)) === 'snapshot', 'not from the snapshot');
    await page.context().close();
  });

  await check('formulas: held while the first numbers come, then every one typeset (a share link)', async () => {
    const page = await newPage();
    const share = golden('04_ind380_7k5.json').input;
    await page.goto(`${ctx.subSrv.url}#in=${encodeURIComponent(JSON.stringify(share))}`);
    await numbersIs(page, 'live', 60_000);
    await page.waitForFunction(() => document.querySelectorAll('[data-tex]').length > 20 && !document.querySelector('[data-tex]:empty'), null, { timeout: 5000 });
    const { formulas, typeset, errors } = await page.evaluate(() => ({
      formulas: document.querySelectorAll('[data-tex]').length,
      typeset: document.querySelectorAll('[data-tex] > .katex, [data-tex] > .katex-display').length,
      errors: document.querySelectorAll('[data-tex] .katex-error').length,
    }));
    assert(typeset === formulas && errors === 0, `${typeset} of ${formulas} formulas typeset, ${errors} KaTeX errors`);
    await page.context().close();
  });

  await check('a new report patches the pure panels in place: the same elements show the new numbers, the rest is untouched; once idle every panel is laid out', async () => {
    const page = await newPage();
    await page.goto(ctx.subSrv.url);
    await numbersIs(page, 'live', 60_000);
    // Expando properties (not attributes: patching sets attributes to the new render's).
    await page.evaluate(() => {
      for (const k of ['base.Z_b', 'base.U_b']) document.querySelector(`[data-key="${k}"]`).pulabProbe = k;
      document.querySelector('#panel-bases .tex').pulabProbe = 'tex';
    });
    const want = cpython({ ...seed.input, motor: { ...seed.input.motor, rated_current_a: 3 } });
    assert(want.base.Z_b !== seed.expected.base.Z_b && want.base.U_b === seed.expected.base.U_b, 'the case must change Z_b only');
    await page.fill('input[name="motor.rated_current_a"]', '3');
    await ctx.waitValue(page, 'base.Z_b', want.base.Z_b);
    const kept = await page.evaluate(() => [
      document.querySelector('[data-key="base.Z_b"]').pulabProbe, document.querySelector('[data-key="base.U_b"]').pulabProbe,
      document.querySelector('#panel-bases .tex').pulabProbe]);
    assert(JSON.stringify(kept) === JSON.stringify(['base.Z_b', 'base.U_b', 'tex']), `elements replaced: ${JSON.stringify(kept)}`);
    assert(await compareShown(page, want) >= 100, 'patched numbers');
    // The link is written in the task that shows the numbers (docs/contract.md).
    const linked = await page.evaluate(() => JSON.parse(decodeURIComponent(location.hash.slice('#in='.length).split('&')[0])));
    assert(linked.motor.rated_current_a === 3, `the link does not say the new input: ${JSON.stringify(linked.motor)}`);
    // Another formula at the same place is drawn anew (U_b = U_LL/√3 → √(2/3)·U_LL).
    const ubRoots = () => page.$$eval('table.bases tbody tr:nth-child(1) td:nth-child(2) .sqrt', (e) => e.length);
    const rootsBefore = await ubRoots();
    await page.selectOption('select[name="conventions.base"]', 'peak');
    await ctx.waitValue(page, 'base.U_b', cpython({ ...seed.input, motor: { ...seed.input.motor, rated_current_a: 3 }, conventions: { ...seed.input.conventions, base: 'peak' } }).base.U_b);
    const texts = await page.$eval('table.bases tbody tr:nth-child(1) td:nth-child(2)', (e) => e.textContent);
    assert(rootsBefore === 1 && await ubRoots() === 1 && texts.includes('2') && texts.includes('3'), `U_b formula not redrawn: ${texts}`);
    // Once idle after live numbers, no panel is skipped any more (full-page screenshots, printing).
    await page.waitForSelector('main.panels.settled', { timeout: 10_000 });
    const skipped = await page.$$eval('section.panel', (els) => els.filter((e) => getComputedStyle(e).contentVisibility !== 'visible').map((e) => e.id));
    assert(skipped.length === 0, `panels still skipped: ${skipped}`);
    // A language switch builds the page again: still every panel laid out.
    await page.click('.lang button:has-text("中文")');
    await page.waitForSelector('html[lang="zh-CN"]');
    assert(await page.$('main.panels.settled') !== null, 'the page built again skips panels off screen');
    await page.context().close();
  });

  await check('no SharedWorker (Chrome for Android) → a dedicated Worker, live golden numbers', async () => {
    const page = await newPage();
    await page.addInitScript(() => {
      delete window.SharedWorker;
    });
    await page.goto(`${ctx.subSrv.url}#in=${encodeURIComponent(JSON.stringify(golden('04_ind380_7k5.json').input))}`);
    await numbersIs(page, 'live', 60_000);
    assert((await page.evaluate(() => document.documentElement.dataset.runtime)) === 'dedicated', 'not dedicated');
    assert(await compareShown(page, golden('04_ind380_7k5.json').expected) >= 60, 'numbers');
    await page.context().close();
  });

  await check('embeds share one runtime per kind: 4 iframes → ≤ 2 shared workers, 0 dedicated, every frame "live"', async () => {
    const panels = ['bases', 'vendor', 'current', 'pll'];
    const page = await newPage();
    const host = `<!doctype html><meta charset="utf-8"><title>host</title>${panels.map((p) => `<iframe src="./?embed=${p}" width="800" height="300"></iframe>`).join('')}`;
    await page.route(`${ctx.subSrv.url}host.html`, (r) => r.fulfill({ body: host, contentType: 'text/html' }));
    const w = await watchWorkers(browser, page);
    await page.goto(`${ctx.subSrv.url}host.html`);
    while (page.frames().length < 1 + panels.length) await page.waitForTimeout(20);
    const frames = page.frames().filter((f) => f !== page.mainFrame());
    await Promise.all(frames.map((f) => f.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 90_000, polling: 50 })));
    await page.waitForTimeout(2000); // the simulation runtime of the plot panels
    const started = w.kinds;
    await w.stop();
    assert(started.filter((k) => k === 'worker').length === 0, `dedicated workers: ${started.join(',')}`);
    const shared = started.filter((k) => k === 'shared_worker').length;
    assert(shared >= 1 && shared <= 2, `runtimes: ${started.join(',') || 'none seen'}`);
    for (const f of frames) assert((await f.$$('section.panel')).length === 1, 'one panel per embed');
    await page.context().close();
  });

  await check('the simulation runtime starts only when a plot comes near the viewport (1 runtime at the top of the page, 2 at the plots)', async () => {
    const page = await newPage();
    const { kinds, stop } = await watchWorkers(browser, page);
    await page.goto(ctx.subSrv.url);
    await numbersIs(page, 'live', 60_000);
    await page.waitForTimeout(1500); // a simulation would have been asked for 400 ms after the report
    const atTop = kinds.length;
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 60_000 });
    await stop();
    assert(atTop === 1, `runtimes started before scrolling to a plot: ${atTop}`);
    assert(kinds.length === 2, `runtimes after scrolling to the plots: ${kinds.length}`);
    await page.context().close();
  });

  await check('server: precompressed zstd/brotli/gzip by Accept-Encoding, ETag/Last-Modified → 304, hashed files immutable', async () => {
    const base = ctx.subSrv.url;
    const html = await fetch(base, { headers: { 'accept-encoding': 'identity' } });
    assert(html.headers.get('etag') && html.headers.get('last-modified'), 'no validators');
    assert(html.headers.get('content-security-policy') === ctx.CSP, 'CSP header');
    const again = await fetch(base, { headers: { 'if-none-match': html.headers.get('etag') } });
    assert(again.status === 304, `If-None-Match → ${again.status}`);
    const since = await fetch(base, { headers: { 'if-modified-since': html.headers.get('last-modified') } });
    assert(since.status === 304, `If-Modified-Since → ${since.status}`);
    // zstd first where the browser takes it (Chromium sends "gzip, deflate, br, zstd"): the snapshot and the wasm
    for (const f of ['pyodide.asm.wasm', readdirSync(join(ROOT, 'dist/pyodide')).find((x) => /^snapshot-.*\.bin$/.test(x))]) {
      const z = await fetch(`${base}pyodide/${f}`, { headers: { 'accept-encoding': 'gzip, deflate, br, zstd' } });
      assert(z.headers.get('content-encoding') === 'zstd', `${f} not zstd: ${z.headers.get('content-encoding')}`);
      // Node 20's fetch does not decode zstd (the build checks that each twin decodes to its file)
      const body = Buffer.from(await z.arrayBuffer());
      assert(body.equals(readFileSync(join(ROOT, 'dist/pyodide', `${f}.zst`))) || body.equals(readFileSync(join(ROOT, 'dist/pyodide', f))), `${f}: not its zstd twin`);
    }
    const wasm = await fetch(`${base}pyodide/pyodide.asm.wasm`, { headers: { 'accept-encoding': 'gzip, br' } });
    assert(wasm.headers.get('content-encoding') === 'br' && wasm.headers.get('content-type') === 'application/wasm', 'wasm not brotli');
    const gz = await fetch(`${base}pyodide/pyodide.asm.wasm`, { headers: { 'accept-encoding': 'gzip' } });
    assert(gz.headers.get('content-encoding') === 'gzip', 'no gzip');
    const snap = readdirSync(join(ROOT, 'dist/pyodide')).find((f) => /^snapshot-.*\.bin$/.test(f));
    const s = await fetch(`${base}pyodide/${snap}`, { method: 'HEAD', headers: { 'accept-encoding': 'br' } });
    assert(/immutable/.test(s.headers.get('cache-control') ?? ''), 'hashed snapshot not immutable');
    assert(/no-cache/.test(html.headers.get('cache-control') ?? ''), 'index.html must revalidate');
    const assets = readdirSync(join(ROOT, 'dist/assets'));
    const missing = assets.filter((f) => /\.(js|css)$/.test(f) && statSync(join(ROOT, 'dist/assets', f)).size >= 1024 && !assets.includes(`${f}.br`));
    assert(missing.length === 0, `no .br for ${missing.join(', ')}`);
  });
}
