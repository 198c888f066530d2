#!/usr/bin/env node
// End-to-end: build, serve dist/ (at / and at a sub-path, with the README's CSP), drive
// /usr/bin/chromium through playwright-core, run every suite in tests/e2e/suites/*.mjs (in name
// order), then the checks that hold over all of them (no off-origin request, no console error).
// No Chromium: a loud SKIPPED line and exit 0 — unless CI is set, then failure.
//
//   node tests/e2e/run.mjs                 build, then every suite
//   node tests/e2e/run.mjs core harden     only the suites whose file name contains a word given
//   E2E_NO_BUILD=1 node tests/e2e/run.mjs  reuse dist/ as it is
//
// A suite is `export default async function (ctx)`; ctx holds the harness below: check, assert,
// newPage, compareShown, golden, cpython, cpythonMany, ready, valueOf, waitValue, leaves, close,
// rootSrv/subSrv ({url, server}), serve(prefix, faults) for another server, SUB, origins, browser,
// ROOT, SHOTS, GOLDEN, CSP, timings.
import { existsSync, mkdirSync, readFileSync, readdirSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { join } from 'node:path';
import { CSP, serve } from './serve.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';
const SHOTS = join(ROOT, 'tests/e2e/screenshots');
const GOLDEN = join(ROOT, 'tests/golden');
const SUITES = join(ROOT, 'tests/e2e/suites');

if (!existsSync(CHROMIUM)) {
  const line = `SKIPPED: e2e (no chromium at ${CHROMIUM}; apt-get install -y chromium)`;
  console.log(`\n${'!'.repeat(line.length)}\n${line}\n${'!'.repeat(line.length)}\n`);
  process.exit(process.env.CI ? 1 : 0);
}
const { chromium } = await import('playwright-core');

// ---- tiny harness -------------------------------------------------------------------------
const results = [];
async function check(name, fn) {
  const t0 = Date.now();
  try {
    await fn();
    results.push({ name, ok: true });
    console.log(`  ✓ ${name} (${Date.now() - t0} ms)`);
  } catch (e) {
    results.push({ name, ok: false, e });
    console.log(`  ✗ ${name}\n      ${String(e?.stack ?? e).split('\n').slice(0, 4).join('\n      ')}`);
  }
}
function assert(cond, msg) {
  if (!cond) throw new Error(msg);
}
const close = (a, e) => Math.abs(a - e) <= Math.max(1e-12 * Math.abs(e), 1e-15);

/** Leaves of `expected` as [path, value] (arrays by index). */
function leaves(o, p = '', out = []) {
  if (Array.isArray(o)) o.forEach((v, i) => leaves(v, `${p}.${i}`, out));
  else if (o && typeof o === 'object') for (const [k, v] of Object.entries(o)) leaves(v, p ? `${p}.${k}` : k, out);
  else out.push([p, o]);
  return out;
}
const golden = (f) => JSON.parse(readFileSync(join(GOLDEN, f), 'utf8'));
const cpythonMany = (inputs) =>
  JSON.parse(execFileSync('python3', ['-c', 'import json,sys; from pulab import report; print(json.dumps([report(i) for i in json.load(sys.stdin)]))'], {
    cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: JSON.stringify(inputs),
  }).toString());
const cpython = (input) => cpythonMany([input])[0];

/** Compare every number the page shows (data-key) that the expected report has. */
async function compareShown(page, expected, scope = 'body') {
  const shown = await page.$$eval(`${scope} [data-key][data-value]`, (els) => els.map((e) => [e.dataset.key, e.dataset.value]));
  const want = new Map(leaves(expected).filter(([, v]) => typeof v === 'number'));
  let n = 0;
  const bad = [];
  for (const [k, v] of shown) {
    if (!want.has(k)) continue;
    n++;
    const e = want.get(k);
    const a = JSON.parse(v);
    if (!(Number.isInteger(e) ? a === e : close(a, e))) bad.push(`${k}: page ${a}, expected ${e}`);
  }
  assert(bad.length === 0, `mismatches:\n${bad.slice(0, 10).join('\n')}`);
  return n;
}

// ---- build & serve -------------------------------------------------------------------------
if (!process.env.E2E_NO_BUILD) {
  console.log('e2e: building…');
  execFileSync('npx', ['vite', 'build', '--configLoader', 'runner', '--config', 'web/vite.config.ts', '--logLevel', 'error'], { cwd: ROOT, stdio: 'inherit' });
}
mkdirSync(SHOTS, { recursive: true });
const SUB = '/tools/pu-lab/';
const rootSrv = await serve(join(ROOT, 'dist'), '/');
const subSrv = await serve(join(ROOT, 'dist'), SUB);
const origins = new Set([new URL(rootSrv.url).origin, new URL(subSrv.url).origin]);

const browser = await chromium.launch({
  executablePath: CHROMIUM,
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
});
const offOrigin = [];
const consoleErrors = [];
/** A page in a fresh browser context (own storage), watched for off-origin requests and console errors. */
async function newPage(opts = {}) {
  // The offline cache (dist/sw.js) is off unless a suite asks for it (context: { serviceWorkers: 'allow' }):
  // a Service Worker between the page and the network would change what routing and timings see.
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 }, locale: opts.locale ?? 'en-US', acceptDownloads: true, serviceWorkers: 'block', ...opts.context });
  const page = await ctx.newPage();
  page.on('request', (r) => {
    const u = r.url();
    if (u.startsWith('data:') || u.startsWith('blob:')) return;
    if (!origins.has(new URL(u).origin)) offOrigin.push(u);
  });
  page.on('console', (m) => {
    if (m.type() === 'error') consoleErrors.push(`${m.text()} @ ${page.url().slice(0, 80)}`);
  });
  page.on('pageerror', (e) => consoleErrors.push(`pageerror: ${e.message}`));
  return page;
}
const ready = (page) => page.waitForSelector('[data-key="vendor.Rpm.value"][data-value]', { timeout: 60_000 });
const valueOf = (page, key) => page.$eval(`[data-key="${key}"][data-value]`, (e) => JSON.parse(e.dataset.value));
/** Wait until the number at `key` equals `want` (rel > 0: to that relative tolerance). No eval: CSP. */
const waitValue = (page, key, want, rel = 0, timeout = 30_000) =>
  page.waitForFunction(([k, w, r]) => {
    const e = document.querySelector(`[data-key="${k}"][data-value]`);
    if (!e) return false;
    const v = JSON.parse(e.dataset.value);
    return r ? Math.abs(v - w) <= r * Math.abs(w) : v === w;
  }, [key, want, rel], { timeout });

const timings = {};
const extraServers = [];
const ctx = {
  check, assert, close, leaves, golden, cpython, cpythonMany, compareShown, newPage, ready, valueOf, waitValue,
  browser, rootSrv, subSrv, SUB, origins, ROOT, SHOTS, GOLDEN, CSP, timings,
  /** Another server of dist/ (same origin rules are checked for it): `serve(prefix, faults)`, see serve.mjs. */
  serve: async (prefix, faults) => {
    const s = await serve(join(ROOT, 'dist'), prefix, 0, faults);
    origins.add(new URL(s.url).origin);
    extraServers.push(s.server);
    return s;
  },
};

// ---- suites --------------------------------------------------------------------------------
const only = process.argv.slice(2);
const files = readdirSync(SUITES).filter((f) => f.endsWith('.mjs')).sort()
  .filter((f) => only.length === 0 || only.some((w) => f.includes(w)));
console.log(`e2e: ${subSrv.url} — suites: ${files.join(', ')}`);
for (const f of files) {
  console.log(`e2e suite ${f}`);
  const suite = (await import(pathToFileURL(join(SUITES, f)).href)).default;
  // A suite that throws outside its checks is one failed check, not the end of the run.
  await check(`suite ${f} ran to its end`, () => suite(ctx));
}

// ---- over all suites (last) ----------------------------------------------------------------
await check('zero off-origin requests', async () => assert(offOrigin.length === 0, offOrigin.join('\n')));
await check('zero console errors', async () => assert(consoleErrors.length === 0, consoleErrors.join('\n')));

await browser.close();
rootSrv.server.close();
subSrv.server.close();
for (const s of extraServers) s.close();
console.log(`e2e timings: ${JSON.stringify(timings)}`);
console.log(`e2e screenshots: ${readdirSync(SHOTS).length} in tests/e2e/screenshots/`);
const failed = results.filter((r) => !r.ok);
console.log(`e2e: ${results.length - failed.length} passed, ${failed.length} failed`);
process.exit(failed.length ? 1 : 0);
