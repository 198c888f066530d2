// Hostile page states and faults. Each scenario asserts a message, a usable form and,
// where the cause goes away, recovery; no scenario may raise a pageerror (an uncaught exception or
// an unhandled promise rejection). Fault pages break requests on purpose, so they use their own
// browser contexts (not ctx.newPage, whose console-error check would count the failed loads).
//
//   node tests/e2e/run.mjs harden          (E2E_NO_BUILD=1 to reuse dist/; HARDEN_ONLY=regex for some)
import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createServer, request } from 'node:http';
import { serve } from '../serve.mjs';

/** Linked states (#in=…): [name, JSON text, a named path, a kept [path, value] or null]. Mirrors tests/web/state-check.test.ts. */
const HOSTILE_LINKS = [
  ['toString object in a choice', '{"motor":{"rs_ohm":2},"current_loop":{"method":{"toString":1}}}', 'current_loop.method', ['motor.rs_ohm', 2]],
  ['toString object in sim.current.axis', '{"sim":{"current":{"axis":{"toString":1}}}}', 'sim.current.axis', null],
  ['string in a number field', '{"motor":{"rs_ohm":"1.5"}}', 'motor.rs_ohm', null],
  ['fraction in an integer field', '{"motor":{"pole_pairs":1.5}}', 'motor.pole_pairs', null],
  ['list in a number field', '{"drive":{"ts_s":[1e-4]}}', 'drive.ts_s', null],
  ['string in a boolean', '{"sim":{"current":{"delay":"yes"}}}', 'sim.current.delay', null],
  ['section that is a number', '{"motor":3}', 'motor', null],
  ['unknown section, key with U+2028', '{"bogus\u2028":1,"motor":{"rs_ohm":3}}', '["bogus\\u2028"]', ['motor.rs_ohm', 3]],
  ['__proto__ key', '{"__proto__":{"polluted":1}}', '__proto__', null],
  ['not JSON', '{motor', '#in', null],
  ['a JSON list', '[1,2]', '#in', null],
  ['null', 'null', '#in', null],
];
const isObj = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
/** `b` over `a`, field by field; own keys such as "__proto__" stay plain data. */
function merge(a, b) {
  const out = {};
  for (const [k, v] of [...Object.entries(a), ...Object.entries(b)]) {
    const value = isObj(out[k]) && isObj(v) && Object.hasOwn(out, k) ? merge(out[k], v) : v;
    Object.defineProperty(out, k, { value, enumerable: true, writable: true, configurable: true });
  }
  return out;
}
/** Stored junk: [name, key, value]. */
const HOSTILE_STORAGE = [
  ['units "null"', 'pulab.units.v1', 'null'],
  ['units with an object unit', 'pulab.units.v1', '{"motor.ld_h":{"toString":1}}'],
  ['input "null"', 'pulab.input.v1', 'null'],
  ['input with a valueOf object', 'pulab.input.v1', '{"pll":{"bandwidth_hz":{"valueOf":1}}}'],
  ['language junk', 'pulab.lang', '{"x":1}'],
];

export default async function harden({ check: runCheck, assert, browser, subSrv, ready, waitValue, golden, ROOT, timings }) {
  // HARDEN_ONLY=regex: only the scenarios whose name matches (to rerun a few after a fix).
  const only = process.env.HARDEN_ONLY ? new RegExp(process.env.HARDEN_ONLY) : null;
  const check = (name, fn) => (only && !only.test(name) ? undefined : runCheck(name, fn));
  const seed = golden('01_seed_motor.json').input;
  /** A fresh context; every pageerror (uncaught error, unhandled rejection) is recorded. */
  async function open(opts = {}) {
    const context = await browser.newContext({ viewport: { width: 1366, height: 900 }, locale: 'en-US', serviceWorkers: opts.sw ? 'allow' : 'block' });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    return { context, page, errors };
  }
  const noPageErrors = (errors) => assert(errors.length === 0, `pageerror: ${errors.join(' | ')}`);
  /** The form is there and takes input. */
  async function formUsable(page) {
    await page.waitForSelector('.inputs input[name="motor.rs_ohm"]', { timeout: 30_000 });
    await page.fill('.inputs input[name="motor.rs_ohm"]', '1.6');
  }
  const text = (page, sel) => page.$eval(sel, (e) => e.textContent ?? '');

  // ---- hostile states -----------------------------------------------------------------------
  let hostilePass = 0;
  let n = 0;
  for (const [name, json, named, kept] of HOSTILE_LINKS) {
    await check(`hostile link: ${name} → named at ${named}, form and numbers, link kept until an edit`, async () => {
      const { context, page, errors } = await open();
      // A link is the whole state: the hostile part goes into the seed motor's full input.
      let obj = null;
      try {
        obj = JSON.parse(json);
      } catch { /* not JSON: sent as it is */ }
      const merged = obj && typeof obj === 'object' && !Array.isArray(obj) ? JSON.stringify(merge(seed, obj)) : json;
      const hash = `#in=${encodeURIComponent(merged)}`;
      await page.goto(`${subSrv.url}?h=${n++}${hash}`);
      const banner = await page.waitForSelector('.state-banner', { timeout: 30_000 }).then((e) => e.textContent());
      assert(banner.includes(named), `banner does not name ${named}: ${banner}`);
      if (kept) assert(JSON.parse(await page.$eval(`[name="${kept[0]}"]`, (e) => e.value)) === kept[1], `${kept[0]} not kept`);
      // A named field or section of the form carries a note (or pulab's error) of its own.
      const noted = (f) => {
        const e = [...document.querySelectorAll('.inputs [data-err-for]')].find((x) => x.dataset.errFor === f);
        return e === undefined ? 'none' : e.textContent !== '';
      };
      if ((await page.evaluate(noted, named)) !== 'none') await page.waitForFunction(noted, named, { timeout: 10_000 });
      await page.waitForSelector('html[data-ready="1"]', { timeout: 60_000 });
      await page.waitForTimeout(600);
      assert(await page.evaluate(() => location.hash) === hash, 'the opened link was overwritten');
      // Recovery: a preset replaces the state; numbers, and the address bar follows again.
      await page.selectOption('select[name="preset"]', 'ind380');
      await ready(page);
      await formUsable(page);
      await page.waitForFunction((h) => location.hash !== h, hash, { timeout: 5000 });
      noPageErrors(errors);
      await context.close();
      hostilePass++;
    });
  }
  for (const [name, key, value] of HOSTILE_STORAGE) {
    await check(`hostile storage: ${name} → form and numbers on every load`, async () => {
      const { context, page, errors } = await open();
      await page.goto(subSrv.url);
      await ready(page);
      // A stored input is the whole state too: a hostile field goes into the seed motor's input.
      const stored = key === 'pulab.input.v1' && value.startsWith('{') ? JSON.stringify(merge(seed, JSON.parse(value))) : value;
      await page.evaluate(([k, v]) => localStorage.setItem(k, v), [key, stored]);
      for (let i = 0; i < 2; i++) {
        await page.reload();
        await ready(page);
        await formUsable(page);
      }
      noPageErrors(errors);
      await context.close();
      hostilePass++;
    });
  }
  console.log(`      hostile states passing: ${hostilePass} of ${HOSTILE_LINKS.length + HOSTILE_STORAGE.length}`);

  // ---- faults -------------------------------------------------------------------------------
  // Python runs in a SharedWorker, whose requests Playwright's routing does not see: faults are
  // injected by a proxy in front of the test server instead (per path: 404, abort, fail once,
  // delay, a byte rate), one proxy (one origin, so its own SharedWorkers) per scenario.
  const faults = [];
  const fault = (name, fn) => check(`fault: ${name}`, async () => {
    await fn();
    faults.push(name);
  });
  const live = (page, timeout = 120_000) => page.waitForSelector('html[data-ready="1"] [data-key="vendor.Rpm.value"][data-value]', { timeout });
  const statusText = (page) => text(page, '.status');
  const upstream = new URL(subSrv.url);

  /** Faults by the file's path: `(path) => action | undefined`; `rules` may change at run time. */
  async function faultProxy(rules) {
    const server = createServer((req, res) => {
      const rule = rules.find((r) => r.match.test(req.url) && !r.spent);
      if (rule?.once) rule.spent = true;
      const act = rule?.action;
      if (act === '404') return res.writeHead(404, { 'Content-Type': 'text/plain' }).end('not found');
      if (act === 'abort') return req.socket.destroy();
      const forward = () => {
        const up = request({ host: upstream.hostname, port: upstream.port, path: req.url, method: req.method, headers: req.headers }, (ur) => {
          res.writeHead(ur.statusCode ?? 502, ur.headers);
          if (!act?.rate) return ur.pipe(res);
          // A slow network: at most `rate` bytes a second, in 50 ms slices.
          ur.pause();
          const slice = Math.max(1, Math.round(act.rate / 20));
          let buf = Buffer.alloc(0);
          let ended = false;
          ur.on('data', (c) => (buf = Buffer.concat([buf, c])));
          ur.on('end', () => (ended = true));
          ur.resume();
          const tick = setInterval(() => {
            if (buf.length) {
              res.write(buf.subarray(0, slice));
              buf = buf.subarray(slice);
            } else if (ended) {
              clearInterval(tick);
              res.end();
            }
          }, 50);
          res.on('close', () => clearInterval(tick));
        });
        up.on('error', () => res.destroy());
        req.pipe(up);
      };
      if (act?.delayMs) setTimeout(forward, act.delayMs);
      else forward();
    });
    await new Promise((r) => server.listen(0, '127.0.0.1', r));
    return { url: `http://127.0.0.1:${server.address().port}${upstream.pathname}`, close: () => { server.closeAllConnections?.(); server.close(); } };
  }

  /** A missing runtime file: the page either does not need it, or says what failed; after the fix, live numbers. */
  for (const file of ['python_stdlib.zip', 'pyodide.asm.wasm', 'pyodide-lock.json', 'pyodide.asm.mjs', 'snapshot-']) {
    await fault(`${file} missing → works or a clear message, usable form; reload after the fix → live numbers`, async () => {
      const rules = [{ match: new RegExp(`/pyodide/${file.replace('.', '\\.')}`), action: '404' }];
      const px = await faultProxy(rules);
      const { context, page, errors } = await open();
      await page.goto(px.url);
      const outcome = await Promise.race([
        page.waitForSelector('.status .status-fatal', { timeout: 150_000 }).then(() => 'message'),
        live(page, 150_000).then(() => 'works'),
      ]);
      if (outcome === 'message') {
        const msg = await statusText(page);
        assert(!/\[object Object\]/.test(msg) && /reload/i.test(msg), `unclear message: ${msg}`);
        await formUsable(page);
        rules.length = 0;
        await page.click('.status .status-reload');
      }
      await live(page);
      await formUsable(page);
      console.log(`      ${file} missing: ${outcome}`);
      noPageErrors(errors);
      await context.close();
      px.close();
    });
  }
  await fault('worker script blocked → message, usable form; reload after the fix → live numbers', async () => {
    const rules = [{ match: /\/assets\/worker-[^/]*\.js/, action: 'abort' }];
    const px = await faultProxy(rules);
    const { context, page, errors } = await open();
    await page.goto(px.url);
    await page.waitForSelector('.status .status-fatal', { timeout: 90_000 });
    await formUsable(page);
    rules.length = 0;
    await page.click('.status .status-reload');
    await live(page);
    noPageErrors(errors);
    await context.close();
    px.close();
  });
  await fault('python_stdlib.zip and the snapshot fail once → the boot retries by itself (no reload)', async () => {
    const px = await faultProxy([{ match: /\/pyodide\/python_stdlib\.zip/, action: 'abort', once: true }, { match: /\/pyodide\/snapshot-/, action: 'abort', once: true }]);
    const { context, page, errors } = await open();
    await page.goto(px.url);
    await live(page);
    await formUsable(page);
    noPageErrors(errors);
    await context.close();
    px.close();
  });
  for (const rate of [200_000, 50_000]) {
    await fault(`slow network (${rate / 1000} KB/s for Python's files) → progress, then live numbers; no timeout`, async () => {
      const px = await faultProxy([{ match: /\/pyodide\//, action: { rate } }]);
      const { context, page, errors } = await open();
      const t0 = Date.now();
      await page.goto(px.url);
      await formUsable(page);
      await live(page, 600_000);
      console.log(`      ${rate / 1000} KB/s: live numbers after ${((Date.now() - t0) / 1000).toFixed(0)} s`);
      assert(!(await page.$('.status .status-fatal')), 'boot failed');
      noPageErrors(errors);
      await context.close();
      px.close();
    });
  }
  await fault('plot library blocked → message and retry at the plot; retry after the fix → plot', async () => {
    const rules = [{ match: /\/assets\/plotly[^/]*\.js/, action: 'abort' }];
    const px = await faultProxy(rules);
    const { context, page, errors } = await open();
    await page.goto(px.url);
    await live(page);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .plot-error button.plot-retry', { timeout: 60_000 });
    await formUsable(page);
    rules.length = 0;
    await page.click('.panel-current .plot-retry');
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 60_000 });
    noPageErrors(errors);
    await context.close();
    px.close();
  });
  await fault('plot library slow (3 s) → loading, then the plot, no error', async () => {
    const px = await faultProxy([{ match: /\/assets\/plotly[^/]*\.js/, action: { delayMs: 3000 } }]);
    const { context, page, errors } = await open();
    await page.goto(px.url);
    await live(page);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 60_000 });
    noPageErrors(errors);
    await context.close();
    px.close();
  });
  await fault('offline right after the first numbers → the plots say so with a retry; online again → plots', async () => {
    const rules = [];
    const px = await faultProxy(rules);
    const { context, page, errors } = await open();
    await page.goto(px.url);
    await live(page);
    rules.push({ match: /./, action: 'abort' }); // the simulation runtime starts after the first report: its boot fails
    await context.setOffline(true);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.fill('.inputs input[name="motor.rs_ohm"]', '1.6');
    await page.waitForSelector('.panel-current .sim-error button.sim-retry', { timeout: 150_000 });
    await formUsable(page);
    rules.length = 0;
    await context.setOffline(false); // 'online' → retried by itself
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 120_000 });
    noPageErrors(errors);
    await context.close();
    px.close();
  });
  /** Kill a runtime (as a crash would): its SharedWorker target closed through CDP. */
  async function killRuntime(page, kind) {
    // Shared workers of this page's browser context only (others may still be winding down).
    const own = await page.context().newCDPSession(page);
    const { targetInfo } = await own.send('Target.getTargetInfo');
    await own.detach();
    const cdp = await browser.newBrowserCDPSession();
    const { targetInfos } = await cdp.send('Target.getTargets');
    const t = targetInfos.find((x) => x.type === 'shared_worker' && x.title === `pulab-${kind}` && x.browserContextId === targetInfo.browserContextId);
    assert(t, `no pulab-${kind} shared worker`);
    await cdp.send('Target.closeTarget', { targetId: t.targetId });
    await cdp.detach();
  }
  await fault('report runtime killed → detected, a message, restarted; the next input gets live numbers', async () => {
    const { context, page, errors } = await open();
    await page.goto(subSrv.url);
    await live(page);
    await killRuntime(page, 'report');
    const t0 = Date.now();
    await page.fill('.inputs input[name="motor.rs_ohm"]', '1.7');
    await page.waitForFunction(() => /restart/i.test(document.querySelector('.status')?.textContent ?? ''), null, { timeout: 30_000 });
    await page.waitForFunction(() => document.documentElement.dataset.runtimeRestarts === '1' && document.documentElement.dataset.ready === '1', null, { timeout: 120_000 });
    await waitValue(page, 'pu.Rs', 0.229242018648822 * 1.7 / 1.5, 1e-9, 60_000); // Rs/Z_b of the new input
    console.log(`      report runtime killed: numbers again after ${Date.now() - t0} ms`);
    noPageErrors(errors);
    await context.close();
  });
  await fault('simulation runtime killed → message and retry at the plot; retry → plot', async () => {
    const { context, page, errors } = await open();
    await page.goto(subSrv.url);
    await live(page);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 120_000 });
    await killRuntime(page, 'sim');
    await page.fill('.inputs input[name="motor.rs_ohm"]', '1.8');
    await page.waitForSelector('.panel-current .sim-error button.sim-retry', { timeout: 60_000 });
    await formUsable(page);
    await page.click('.panel-current .sim-retry');
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 120_000 });
    noPageErrors(errors);
    await context.close();
  });
  await check('measured: a new input while the worst allowed simulation runs → the running one is cancelled, the new result arrives (latency printed)', async () => {
    const { context, page, errors } = await open();
    const worst = merge(seed, { current_loop: { method: 'integers', pm_kp: 2 ** 31 - 1, pm_ki: 2 ** 31 - 1 },
      sim: { current: { duration_s: 200000 * 1e-4 }, pll: { duration_s: 500000 * 1e-4 } } });
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(worst))}`);
    await live(page);
    // The simulation runtime starts only when a plot panel comes near the screen.
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForFunction(() => document.documentElement.dataset.simPosted === '1', null, { timeout: 60_000 });
    await page.waitForTimeout(1000); // the worst simulation is running now (it takes several seconds)
    // Page-side timestamps of the counters <html data-sim-posted/-superseded/-done>.
    const t0 = await page.evaluate(() => {
      const seen = {};
      window.__simTimes = seen;
      new MutationObserver(() => {
        const d = document.documentElement.dataset;
        for (const k of ['simPosted', 'simSuperseded', 'simDone']) seen[`${k}=${d[k]}`] ??= performance.now();
      }).observe(document.documentElement, { attributes: true });
      return performance.now();
    });
    await page.selectOption('select[name="preset"]', 'seed');
    await page.waitForFunction(() => Number(document.documentElement.dataset.simDone ?? 0) >= 1, null, { timeout: 300_000 });
    const seen = await page.evaluate(() => window.__simTimes);
    assert(await page.evaluate(() => document.documentElement.dataset.simSuperseded) === '1', 'the worst simulation was not cancelled');
    const posted = seen['simPosted=2'] - t0;
    const cancelled = seen['simSuperseded=1'] - t0;
    const done = seen['simDone=1'] - t0;
    timings.new_sim_behind_worst_ms = Math.round(done);
    timings.sim_cancel_ms = Math.round(cancelled - posted);
    console.log(`      new input during the worst simulation: posted after ${posted.toFixed(0)} ms (the typing pause), old one cancelled ${(cancelled - posted).toFixed(0)} ms after the post, new result after ${done.toFixed(0)} ms`);
    // The latency is printed, not asserted: a shared 2-core machine's load decides it (the
    // bench measures it); what is checked is that the old run was superseded and the new one done.
    assert(seen['simSuperseded=1'] !== undefined && seen['simDone=1'] !== undefined, 'no cancellation or no new result seen');
    noPageErrors(errors);
    await context.close();
  });
  await fault('page code chunk blocked → a message and a reload button; reload after the fix → numbers', async () => {
    const rules = [{ match: /\/assets\/app-[^/]*\.js/, action: 'abort' }];
    const px = await faultProxy(rules);
    const { context, page, errors } = await open();
    await page.goto(px.url);
    await page.waitForSelector('#app .load-failed button', { timeout: 30_000 });
    rules.length = 0;
    await page.click('#app .load-failed button');
    await live(page);
    await formUsable(page);
    noPageErrors(errors);
    await context.close();
    px.close();
  });
  await fault('stylesheet and KaTeX fonts blocked → numbers and form still work', async () => {
    const px = await faultProxy([{ match: /\/assets\/[^/]*\.(css|woff2?|ttf)/, action: 'abort' }]);
    const { context, page, errors } = await open();
    await page.goto(px.url);
    await live(page);
    await formUsable(page);
    noPageErrors(errors);
    await context.close();
    px.close();
  });

  // Offline after one visit, and no stale code after a new deployment: a copy of dist/ that this
  // suite serves, stops and changes.
  const dir = mkdtempSync(join(tmpdir(), 'pulab-offline-'));
  cpSync(join(ROOT, 'dist'), dir, { recursive: true });
  let srv = await serve(dir, '/off/');
  const port = new URL(srv.url).port;
  const stop = () => new Promise((res) => {
    srv.server.closeAllConnections?.();
    srv.server.close(res);
  });
  const sw = await open({ sw: true });
  const cached = () => sw.page.evaluate(async () => {
    const keys = await caches.keys();
    const c = keys.length ? await caches.open(keys[0]) : null;
    return { keys, controlled: navigator.serviceWorker.controller !== null, wasm: c ? (await c.match('pyodide/pyodide.asm.wasm')) !== undefined : false };
  });
  await fault('after one visit the site reloads and works offline', async () => {
    await sw.page.goto(srv.url);
    await ready(sw.page);
    for (let i = 0; i < 120 && !(await cached()).wasm; i++) await sw.page.waitForTimeout(500);
    assert((await cached()).wasm, `offline cache not filled: ${JSON.stringify(await cached())}`);
    await stop();
    await sw.page.reload();
    await ready(sw.page);
    await formUsable(sw.page);
    noPageErrors(sw.errors);
  });
  await fault('a new deployment is served at once, not the cached code', async () => {
    const index = join(dir, 'index.html');
    writeFileSync(index, readFileSync(index, 'utf8').replace('<head>', '<head><meta name="pulab-deploy" content="B">'));
    const swFile = join(dir, 'sw.js');
    writeFileSync(swFile, readFileSync(swFile, 'utf8').replace(/const VERSION = "([^"]+)"/, 'const VERSION = "$1-b"'));
    // A real build writes their precompressed twins too; here the stale twins go.
    for (const f of [index, swFile]) for (const z of ['.zst', '.br', '.gz']) rmSync(f + z, { force: true });
    srv = await serve(dir, '/off/', Number(port));
    await sw.page.reload();
    await ready(sw.page);
    assert(await sw.page.$('meta[name="pulab-deploy"][content="B"]') !== null, 'the old index.html was served');
    // The new version precaches the whole build, then deletes the old cache.
    const onlyNew = (keys) => keys.length === 1 && keys[0].endsWith('-b');
    for (let i = 0; i < 240 && !onlyNew((await cached()).keys); i++) await sw.page.waitForTimeout(500);
    const keys = (await cached()).keys;
    assert(keys.length === 1 && keys[0].endsWith('-b'), `old caches kept: ${keys}`);
    noPageErrors(sw.errors);
  });
  await sw.context.close();
  await stop();
  rmSync(dir, { recursive: true, force: true });
  console.log(`      fault scenarios passing here: ${faults.length}`);
}
