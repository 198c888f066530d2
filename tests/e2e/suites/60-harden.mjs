// Issue 14: hostile page states and faults. Each scenario asserts a message, a usable form and,
// where the cause goes away, recovery; no scenario may raise a pageerror (an uncaught exception or
// an unhandled promise rejection). Fault pages break requests on purpose, so they use their own
// browser contexts (not ctx.newPage, whose console-error check would count the failed loads).
//
//   node tests/e2e/run.mjs harden          (E2E_NO_BUILD=1 to reuse dist/)
import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
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
  ['input with a valueOf object', 'pulab.input.v1', '{"motor":{"rs_ohm":{"valueOf":1}}}'],
  ['language junk', 'pulab.lang', '{"x":1}'],
];

export default async function harden({ check, assert, browser, subSrv, ready, golden, ROOT }) {
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
      await page.evaluate(([k, v]) => localStorage.setItem(k, v), [key, value]);
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
  const faults = [];
  const fault = (name, fn) => check(`fault: ${name}`, async () => {
    await fn();
    faults.push(name);
  });
  const statusText = (page) => text(page, '.status');
  /** Boot fails on a missing runtime file: a message naming it, the form usable, a reload recovers. */
  for (const file of ['python_stdlib.zip', 'pyodide.asm.wasm', 'pyodide-lock.json', 'pyodide.asm.mjs']) {
    await fault(`${file} missing → message, usable form; reload after the fix → numbers`, async () => {
      const { context, page, errors } = await open();
      await context.route(`**/pyodide/${file}`, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.goto(subSrv.url);
      await page.waitForSelector('.status .status-fatal', { timeout: 90_000 });
      const msg = await statusText(page);
      assert(!/\[object Object\]/.test(msg), `unclear message: ${msg}`);
      await formUsable(page);
      await context.unroute(`**/pyodide/${file}`);
      await page.reload();
      await ready(page);
      noPageErrors(errors);
      await context.close();
    });
  }
  await fault('worker chunk blocked → message, usable form; reload → numbers', async () => {
    const { context, page, errors } = await open();
    await context.route('**/assets/worker-*.js', (r) => r.abort());
    await page.goto(subSrv.url);
    await page.waitForSelector('.status .status-fatal', { timeout: 90_000 });
    await formUsable(page);
    await context.unroute('**/assets/worker-*.js');
    await page.reload();
    await ready(page);
    noPageErrors(errors);
    await context.close();
  });
  await fault('python_stdlib.zip fails once → the boot retries by itself', async () => {
    const { context, page, errors } = await open();
    let failed = 0;
    await context.route('**/pyodide/python_stdlib.zip', (r) => (failed++ === 0 ? r.abort() : r.continue()));
    await page.goto(subSrv.url);
    await ready(page);
    noPageErrors(errors);
    await context.close();
  });
  await fault('plot library blocked → message and retry at the plot; retry after the fix → plot', async () => {
    const { context, page, errors } = await open();
    await context.route('**/assets/plotly*.js', (r) => r.abort());
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .plot-error button.plot-retry', { timeout: 30_000 });
    await formUsable(page);
    await context.unroute('**/assets/plotly*.js');
    await page.click('.panel-current .plot-retry');
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 30_000 });
    noPageErrors(errors);
    await context.close();
  });
  await fault('plot library slow (3 s) → loading, then the plot, no error', async () => {
    const { context, page, errors } = await open();
    await context.route('**/assets/plotly*.js', async (r) => {
      await new Promise((res) => setTimeout(res, 3000));
      await r.continue();
    });
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 30_000 });
    noPageErrors(errors);
    await context.close();
  });
  await fault('offline right after the first numbers → the plots say so with a retry; online again → plots', async () => {
    const { context, page, errors } = await open();
    await page.goto(subSrv.url);
    await ready(page);
    await context.setOffline(true); // the simulation worker starts after the first report: its boot fails
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .sim-error button.sim-retry', { timeout: 90_000 });
    await formUsable(page);
    await context.setOffline(false); // 'online' → retried by itself
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 90_000 });
    noPageErrors(errors);
    await context.close();
  });
  await fault('page code chunk blocked → a message and a reload button; reload after the fix → numbers', async () => {
    const { context, page, errors } = await open();
    await context.route('**/assets/app-*.js', (r) => r.abort());
    await page.goto(subSrv.url);
    await page.waitForSelector('#app .load-failed button', { timeout: 30_000 });
    await context.unroute('**/assets/app-*.js');
    await page.click('#app .load-failed button');
    await ready(page);
    await formUsable(page);
    noPageErrors(errors);
    await context.close();
  });
  await fault('stylesheet and KaTeX fonts blocked → numbers and form still work', async () => {
    const { context, page, errors } = await open();
    await context.route(/\/assets\/.*\.(css|woff2?|ttf)$/, (r) => r.abort());
    await page.goto(subSrv.url);
    await ready(page);
    await formUsable(page);
    noPageErrors(errors);
    await context.close();
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
    srv = await serve(dir, '/off/', Number(port));
    await sw.page.reload();
    await ready(sw.page);
    assert(await sw.page.$('meta[name="pulab-deploy"][content="B"]') !== null, 'the old index.html was served');
    for (let i = 0; i < 60 && (await cached()).keys.length !== 1; i++) await sw.page.waitForTimeout(500);
    const keys = (await cached()).keys;
    assert(keys.length === 1 && keys[0].endsWith('-b'), `old caches kept: ${keys}`);
    noPageErrors(sw.errors);
  });
  await sw.context.close();
  await stop();
  rmSync(dir, { recursive: true, force: true });
  console.log(`      fault scenarios passing here: ${faults.length}`);
}
