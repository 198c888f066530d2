// `npm run bench`, page side (issues 4 and 8; prints numbers, not a test): in headless Chromium
// on the built dist/, served by tests/e2e/serve.mjs (compression, validators), each scenario
// BENCH_RUNS times (default 5), medians with min–max, the machine's load average before/after:
//   default page cold (fresh profile) and warm (reload), share link cold (#in=, not the seed),
//   a page with 6 different ?embed= iframes (runtimes started, time to all live, PSS of Chromium),
//   a docs page of another origin with 12 <pu-lab-panel> (the same numbers),
//   input → all numbers updated (in page, dataset.updateMs), typed by Playwright fill and by keyboard events,
//   typing: keystroke → numbers and answer strip current, Inovance and Microchip side by side (fresh profiles).
// Each boot is printed in phases (ms since navigation) from <html data-t-…> marks.
//   sim: the seed's simulations, 8 in a row, in the simulation runtime alone (the worker's time).
//   floor: a blank page that only starts the report runtime from its snapshot (the build's own
//   worker script, no page code) and asks it for the share link's report before it is ready.
// BENCH_NO_BUILD=1 reuses dist/ (BENCH_DIST=dir: another build); BENCH_SCENARIOS=floor,floordedicated,sim,cold,warm,share,nosnap,embeds,panel,elements,input,typing
// picks scenarios (nosnap: cold with the snapshot refused, the fallback boot).
import { existsSync, mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { loadavg, tmpdir } from 'node:os';
import { createServer } from 'node:http';
import { serve } from './serve.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';
if (!existsSync(CHROMIUM)) {
  console.log(`page bench SKIPPED (no chromium at ${CHROMIUM})`);
  process.exit(0);
}
const RUNS = Number(process.env.BENCH_RUNS ?? 5);
const SETTLE = process.env.BENCH_SETTLE !== '0'; // see settle()
/** The profile marker in the command line of the Chromium this script launches (Playwright's). */
const MARK = 'playwright_chromium';
const SCEN = new Set((process.env.BENCH_SCENARIOS ?? 'floor,sim,cold,warm,share,nosnap,embeds,panel,elements,input,typing').split(','));
const DIST = process.env.BENCH_DIST ?? join(ROOT, 'dist');
const { chromium } = await import('playwright-core');
if (!process.env.BENCH_NO_BUILD) execFileSync('npx', ['vite', 'build', '--configLoader', 'runner', '--config', 'web/vite.config.ts', '--logLevel', 'error'], { cwd: ROOT, stdio: 'inherit' });
const SHARE_INPUT = JSON.parse(readFileSync(join(ROOT, 'tests/golden/04_ind380_7k5.json'), 'utf8')).input;
const { server, url } = await serve(DIST, '/bench/', 0, { extra: { ...floorPage(), ...simPage() } });
// The fallback boot: the same build with its snapshot refused (404).
const nosnap = await serve(DIST, '/bench/', 0, { refuse: /snapshot-.*\.bin$/ });
const load0 = loadavg();
const CHROMIUM_ARGS = ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'];
let browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
const q = (a, f) => [...a].sort((x, y) => x - y)[Math.min(a.length - 1, Math.floor(f * a.length))];
const stat = (a) => (a.some((x) => x === Infinity) ? `> 240 s in ${a.filter((x) => x === Infinity).length} of ${a.length} runs` : a.length ? `${q(a, 0.5).toFixed(0)} ms (${Math.min(...a).toFixed(0)}–${Math.max(...a).toFixed(0)})` : 'n/a');
const PHASES = ['app', 'numbers', 'bootRuntime', 'bootSnapshot', 'bootFiles', 'bootImport', 'bootReady', 'live'];
// Live: Python computed the input in the form (data-numbers="live"; a build without that attribute
// showed only live numbers, so for it the first number counts).
const isLive = () => {
  const n = document.documentElement.dataset.numbers;
  return n ? n === 'live' : !!document.querySelector('[data-key="vendor.Rpm.value"][data-value], [data-key][data-value]');
};
const waitLive = (p, timeout = 90_000) => p.waitForFunction(isLive, null, { timeout, polling: 20 });
const waitFirst = (p) => p.waitForFunction(() => /^(build|cached|live)$/.test(document.documentElement.dataset.numbers ?? '') || !!document.querySelector('[data-key="vendor.Rpm.value"][data-value]'), null, { timeout: 90_000, polling: 10 });

/**
 * One navigation: wall-clock to first numbers and to live, and the page's own phase marks; with
 * `mark` (the browser's profile marker), the CPU time its processes used until live — steadier
 * than the wall clock on a machine whose speed drifts, so variants compare by it too.
 */
async function boot(p, target, mark = null) {
  const c0 = mark ? cpuOfBrowser(mark) : 0;
  const t0 = Date.now();
  await p.goto(target, { waitUntil: 'commit' });
  await waitFirst(p);
  const first = Date.now() - t0;
  await waitLive(p);
  const live = Date.now() - t0;
  const cpu = mark ? cpuOfBrowser(mark) - c0 : undefined;
  const d = await p.evaluate(() => ({ ...document.documentElement.dataset }));
  const phases = Object.fromEntries(PHASES.filter((k) => d[`t${k[0].toUpperCase()}${k.slice(1)}`] !== undefined).map((k) => [k, Number(d[`t${k[0].toUpperCase()}${k.slice(1)}`])]));
  return { first, live, cpu, phases, from: d.pythonBoot, runtime: d.runtime, numbers0: d.numbers };
}
function report(name, runs) {
  console.log(`page: ${name.padEnd(30)} first numbers ${stat(runs.map((r) => r.first))}   live ${stat(runs.map((r) => r.live))}   [${runs[0]?.from ?? '?'} boot, ${runs[0]?.runtime ?? '?'} worker]`);
  const ph = PHASES.map((k) => [k, runs.map((r) => r.phases[k]).filter((v) => v !== undefined)]).filter(([, v]) => v.length);
  console.log(`      phases (median ms since navigation): ${ph.map(([k, v]) => `${k} ${q(v, 0.5).toFixed(0)}`).join(' → ')}`);
  const cpu = runs.map((r) => r.cpu).filter((v) => v !== undefined);
  if (cpu.length) console.log(`      CPU of all the browser's processes until live: ${stat(cpu)} (two cores)`);
}
const newCtx = () => browser.newContext({ viewport: { width: 1366, height: 768 } });
/** A new context's page, once its window has settled (settle()). */
async function freshPage() {
  const ctx = await newCtx();
  const p = await ctx.newPage();
  await settle(MARK);
  return { ctx, p };
}
/** The build's worker script (its hashed name). */
function workerScript() {
  return readdirSync(join(DIST, 'assets')).find((f) => /^worker-.*\.js$/.test(f));
}

/**
 * The floor: floor.html starts the build's worker script as the page does (a SharedWorker named
 * as the page's report runtime), posts init and the share link's report at once, and marks each
 * boot stage, ready and the report's answer (<html data-t-…>, ms since navigation).
 */
function floorPage() {
  const worker = workerScript();
  const js = `const d = document.documentElement.dataset;
const mark = (k) => { d[k] ??= performance.now().toFixed(0); };
const dedicated = new URLSearchParams(location.search).has('dedicated');
const u = new URL('./assets/${worker}', document.baseURI);
const w = dedicated ? new Worker(u, { type: 'module', name: 'pulab-report' }) : new SharedWorker(u, { type: 'module', name: 'pulab-report' });
const port = dedicated ? w : w.port;
port.onmessage = ({ data: m }) => {
  if (m.type === 'progress') { mark('tBoot' + m.stage[0].toUpperCase() + m.stage.slice(1)); d['w' + m.stage] ??= m.ms.toFixed(0); }
  else if (m.type === 'ready') { mark('tBootReady'); d.pythonBoot = m.from ?? 'full'; d.wready = m.bootMs.toFixed(0); }
  else if (m.type === 'result') { mark('tLive'); d.numbers = m.result.ok ? 'live' : 'error'; }
  else if (m.type === 'fatal') d.numbers = 'fatal: ' + m.message;
};
port.postMessage({ type: 'init', indexURL: new URL('pyodide/', document.baseURI).href, timeoutMs: 60000 });
port.postMessage({ type: 'call', id: 1, kind: 'report', payload: ${JSON.stringify(JSON.stringify(SHARE_INPUT))}, channel: 'report' });
`;
  return {
    'floor.html': ['text/html; charset=utf-8', '<!doctype html><meta charset="utf-8"><title>floor</title><script type="module" src="./floor.js"></script>'],
    'floor.js': ['text/javascript', js],
  };
}
/**
 * The simulation runtime alone: simsim.html starts the build's worker script as the page's
 * simulation runtime and asks it, 8 times in a row, for the seed's current and PLL simulations
 * (a report in slices, as the page's plots ask); the worker's own time of each answer.
 */
function simPage() {
  const worker = workerScript();
  const seed = JSON.parse(readFileSync(join(ROOT, 'tests/golden/01_seed_motor.json'), 'utf8')).input;
  const js = `const w = new SharedWorker(new URL('./assets/${worker}', document.baseURI), { type: 'module', name: 'pulab-sim' });
const out = []; let id = 0;
const ask = () => w.port.postMessage({ type: 'call', id: ++id, kind: 'report', payload: ${JSON.stringify(JSON.stringify({ ...seed, sim: { current: {}, pll: {} } }))}, channel: 'sim' });
w.port.onmessage = ({ data: m }) => {
  if (m.type === 'ready') ask();
  if (m.type === 'result') { out.push(m.ms); if (out.length < 8) ask(); else document.documentElement.dataset.ms = JSON.stringify(out); }
};
w.port.postMessage({ type: 'init', indexURL: new URL('pyodide/', document.baseURI).href, timeoutMs: 60000, warm: false });
`;
  return {
    'simsim.html': ['text/html; charset=utf-8', '<!doctype html><meta charset="utf-8"><title>sim</title><script type="module" src="./simsim.js"></script>'],
    'simsim.js': ['text/javascript', js],
  };
}
if (SCEN.has('sim')) {
  const all = [];
  for (let i = 0; i < RUNS; i++) {
    const { ctx, p } = await freshPage();
    await p.goto(`${url}simsim.html`, { waitUntil: 'commit' });
    await p.waitForFunction(() => document.documentElement.dataset.ms, null, { timeout: 120_000, polling: 50 });
    all.push(...JSON.parse(await p.evaluate(() => document.documentElement.dataset.ms)).slice(1)); // the first runs cold
    await ctx.close();
  }
  console.log(`page: the seed's current + PLL simulation in the simulation runtime, warm (${all.length} answers): worker time ${stat(all)}`);
}
// The floor twice, interleaved run by run: with the SharedWorker the page uses, and with a
// dedicated Worker (a SharedWorker is started in a process of its own).
for (const variant of SCEN.has('floor') ? ['shared', ...(SCEN.has('floordedicated') ? ['dedicated'] : [])] : []) {
  const runs = [];
  for (let i = 0; i < RUNS; i++) {
    const { ctx, p } = await freshPage();
    const c0 = cpuOfBrowser(MARK);
    const t0 = Date.now();
    await p.goto(`${url}floor.html${variant === 'dedicated' ? '?dedicated' : ''}`, { waitUntil: 'commit' });
    await p.waitForFunction(() => document.documentElement.dataset.numbers, null, { timeout: 90_000, polling: 10 });
    const wall = Date.now() - t0;
    const cpu = cpuOfBrowser(MARK) - c0;
    const d = await p.evaluate(() => ({ ...document.documentElement.dataset }));
    if (d.numbers !== 'live') throw new Error(`floor page: ${d.numbers}`);
    const phases = Object.fromEntries(PHASES.filter((k) => d[`t${k[0].toUpperCase()}${k.slice(1)}`] !== undefined).map((k) => [k, Number(d[`t${k[0].toUpperCase()}${k.slice(1)}`])]));
    const worker = Object.fromEntries(['runtime', 'snapshot', 'files', 'import', 'ready'].map((k) => [k, Number(d[`w${k}`])]));
    runs.push({ first: phases.bootReady, live: wall, cpu, phases, worker, from: d.pythonBoot, runtime: variant });
    await ctx.close();
  }
  console.log(`page: floor (blank page, runtime only, ${variant} worker)  ready ${stat(runs.map((r) => r.phases.bootReady))} in page   report answered ${stat(runs.map((r) => r.phases.live))} in page, ${stat(runs.map((r) => r.live))} wall   [${runs[0]?.from ?? '?'} boot]`);
  const ph = PHASES.map((k) => [k, runs.map((r) => r.phases[k]).filter((v) => v !== undefined)]).filter(([, v]) => v.length);
  console.log(`      phases (median ms since navigation): ${ph.map(([k, v]) => `${k} ${q(v, 0.5).toFixed(0)}`).join(' → ')}`);
  const w = ['runtime', 'snapshot', 'files', 'import', 'ready'].map((k) => [k, runs.map((r) => r.worker[k]).filter((v) => !Number.isNaN(v))]).filter(([, v]) => v.length);
  console.log(`      in the worker (median ms since its boot began): ${w.map(([k, v]) => `${k} ${q(v, 0.5).toFixed(0)}`).join(' → ')}`);
  console.log(`      CPU of all the browser's processes until answered: ${stat(runs.map((r) => r.cpu))} (two cores)`);
}
if (SCEN.has('cold')) {
  const runs = [];
  for (let i = 0; i < RUNS; i++) {
    const { ctx, p } = await freshPage();
    runs.push(await boot(p, url));
    await ctx.close();
  }
  report('default page, cold profile', runs);
}
if (SCEN.has('warm')) {
  const ctx = await newCtx();
  const p = await ctx.newPage();
  await boot(p, url);
  await p.waitForTimeout(1500); // the cache write of the last report, the simulation runtime
  const runs = [];
  for (let i = 0; i < RUNS; i++) runs.push(await boot(p, `${url}?warm=${i}`));
  await ctx.close();
  report('default page, warm (reload)', runs);
}
if (SCEN.has('share')) {
  const link = `${url}#in=${encodeURIComponent(JSON.stringify(SHARE_INPUT))}`;
  const runs = [];
  for (let i = 0; i < RUNS; i++) {
    const { ctx, p } = await freshPage();
    runs.push(await boot(p, link, MARK));
    await ctx.close();
  }
  report('share link (380 V), cold', runs);
}
if (SCEN.has('nosnap')) {
  const runs = [];
  for (let i = 0; i < RUNS; i++) {
    const { ctx, p } = await freshPage();
    runs.push(await boot(p, nosnap.url));
    await ctx.close();
  }
  report('default page, cold, no snapshot', runs);
}

/**
 * PSS (kB) summed over the Chromium started by this process whose command line contains `mark`
 * (a browser's --user-data-dir), and its descendants (renderers, GPU, utility).
 */
/** The processes of the Chromium whose command line holds `mark` (its profile directory), children included. */
function browserPids(mark) {
  const ppid = new Map();
  for (const d of readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const s = readFileSync(`/proc/${d}/stat`, 'utf8');
      ppid.set(Number(d), Number(s.slice(s.lastIndexOf(')') + 2).split(' ')[1]));
    } catch { /* gone */ }
  }
  const cmdline = (pid) => { try { return readFileSync(`/proc/${pid}/cmdline`, 'utf8'); } catch { return ''; } };
  const mine = new Set([...ppid].filter(([pid, pp]) => pp === process.pid && cmdline(pid).includes(mark)).map(([pid]) => pid));
  let grew = true;
  while (grew) {
    grew = false;
    for (const [pid, pp] of ppid) if (!mine.has(pid) && mine.has(pp)) { mine.add(pid); grew = true; }
  }
  return mine;
}
/** CPU time (ms) the browser's processes have used so far. */
function cpuOfBrowser(mark) {
  let ticks = 0;
  for (const pid of browserPids(mark)) {
    try {
      const s = readFileSync(`/proc/${pid}/stat`, 'utf8');
      const f = s.slice(s.lastIndexOf(')') + 2).split(' '); // from field 3 (state) on
      ticks += Number(f[11]) + Number(f[12]); // utime, stime (fields 14, 15)
    } catch { /* gone */ }
  }
  return ticks * 10; // USER_HZ = 100
}
/**
 * A new window does work of its own before any page is asked for (Chromium 156 headless builds
 * the omnibox popup's WebUI renderer per window: ≈ 0.5 s of two cores in a trace). A user's link
 * opens in a browser whose window has long finished that, so a run navigates once the browser has
 * used under 10 ms of CPU in 300 ms (at most 5 s). BENCH_SETTLE=0: navigate at once, as before.
 */
async function settle(mark) {
  if (!SETTLE) return;
  const until = Date.now() + 5000;
  let last = cpuOfBrowser(mark);
  while (Date.now() < until) {
    await new Promise((r) => setTimeout(r, 300));
    const now = cpuOfBrowser(mark);
    if (now - last < 10) return;
    last = now;
  }
}
function pssOfBrowser(mark) {
  const mine = browserPids(mark);
  let kb = 0;
  for (const pid of mine) {
    try {
      const m = /^Pss:\s+(\d+)/m.exec(readFileSync(`/proc/${pid}/smaps_rollup`, 'utf8'));
      if (m) kb += Number(m[1]);
      if (m && process.env.BENCH_PSS_DETAIL) {
        const cmd = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
        const type = /--type=(\S+?)(\s|\0|$)/.exec(cmd)?.[1] ?? 'browser';
        const sub = /--utility-sub-type=(\S+?)(\s|\0|$)/.exec(cmd)?.[1] ?? (/--extension-process|--webui|--renderer-client-id=\d+/.exec(cmd)?.[0] ?? '');
        console.log(`      PSS ${(Number(m[1]) / 1024).toFixed(1).padStart(6)} MB  ${type} ${sub}`);
      }
    } catch { /* gone */ }
  }
  return { kb, processes: mine.size };
}

const SIX = ['bases', 'pu', 'vendor', 'constants', 'current', 'pll'];
const TWELVE = [...SIX, 'loop', 'qcalc', 'conventions', 'datasheet', 'review', 'vendors'];
/** A docs page of another origin (same site) with 12 <pu-lab-panel>, every other one another motor. */
// A real server on its own port: a page answered by a route has no address, and Chromium refuses
// its requests to the loopback site (local network access).
const elementsServer = createServer((req, res) => res.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8' }).end(req.url?.startsWith('/panel.html') ? panelHost() : elementsHost()));
await new Promise((r) => elementsServer.listen(0, '127.0.0.1', r));
const ELEMENTS_HOST = `http://127.0.0.1:${elementsServer.address().port}/docs.html`;
const PANEL_HOST = `http://127.0.0.1:${elementsServer.address().port}/panel.html`;
const OTHER = { motor: { rated_voltage_v: 380, rated_current_a: 14.5, rated_freq_hz: 50, pole_pairs: 2, rs_ohm: 0.42, ld_h: 0.0085, lq_h: 0.0135, bemf_v: 335 }, drive: { udc_v: 540, ts_s: 0.000125 } };
/** A docs page of another origin with one <pu-lab-panel> of a motor that is not the seed (a cold panel). */
function panelHost() {
  return `<!doctype html><meta charset="utf-8"><title>docs</title><script type="module" src="${url}embed.js"></script><h2>bases</h2><pu-lab-panel panel="bases" input='${JSON.stringify(OTHER)}'></pu-lab-panel>`;
}
function elementsHost() {
  const other = JSON.stringify({ motor: { rated_voltage_v: 380, rated_current_a: 14.5, rated_freq_hz: 50, pole_pairs: 2, rs_ohm: 0.42, ld_h: 0.0085, lq_h: 0.0135, bemf_v: 335 }, drive: { udc_v: 540, ts_s: 0.000125 } });
  return `<!doctype html><meta charset="utf-8"><title>docs</title><script type="module" src="${url}embed.js"></script>`
    + TWELVE.map((p, i) => `<h2>${p}</h2><pu-lab-panel panel="${p}"${i % 2 ? ` input='${other}'` : ''}></pu-lab-panel>`).join('');
}

/**
 * Embedded panels on one host page, in a fresh browser context: 6 different ?embed= iframes of
 * the site's origin, or (`elements`) 12 <pu-lab-panel> on a page of another origin. Runtimes
 * started, time to first and to all-live numbers, PSS of every Chromium process 3 s after all are live.
 */
async function embedsRun(ctx, cdp, mark, elements = false) {
  const panels = elements === 'one' ? ['bases'] : elements ? TWELVE : SIX;
  const hostUrl = elements === 'one' ? PANEL_HOST : elements ? ELEMENTS_HOST : `${url}embed-host.html`;
  const host = elements ? null : `<!doctype html><meta charset="utf-8"><title>embeds</title>${panels.map((p) => `<iframe src="./?embed=${p}" width="900" height="400"></iframe>`).join('')}`;
  if (!elements) await ctx.route(hostUrl, (r) => r.fulfill({ body: host, contentType: 'text/html' }));
  const workers = new Set();
  cdp.on('Target.targetCreated', ({ targetInfo: t }) => {
    if (t.type === 'shared_worker' || t.type === 'worker') workers.add(t.targetId);
  });
  await cdp.send('Target.setDiscoverTargets', { discover: true });
  const p = ctx.pages()[0] ?? await ctx.newPage();
  await settle(mark);
  const t0 = Date.now();
  await p.goto(hostUrl, { waitUntil: 'commit' });
  await p.waitForFunction((n) => document.querySelectorAll('iframe').length === n, panels.length, { timeout: 60_000 });
  const frames = () => p.frames().filter((f) => f !== p.mainFrame());
  while (frames().length < panels.length) await p.waitForTimeout(20);
  const first = await Promise.all(frames().map((f) => f.waitForFunction(() => /^(build|cached|live)$/.test(document.documentElement.dataset.numbers ?? '') || !!document.querySelector('[data-key][data-value]'), null, { timeout: 240_000, polling: 20 }))).then(() => Date.now() - t0, () => Infinity);
  // A build that starts 12 runtimes may not get there under load: recorded as not live.
  const live = await Promise.all(frames().map((f) => f.waitForFunction(isLive, null, { timeout: 240_000, polling: 20 })))
    .then(() => Date.now() - t0, () => Infinity);
  await p.waitForTimeout(3000); // simulations of the plot panels
  const mem = pssOfBrowser(mark);
  await cdp.send('Target.setDiscoverTargets', { discover: false });
  await cdp.detach();
  return { first, live, runtimes: workers.size, pssMB: mem.kb / 1024, processes: mem.processes };
}
function reportEmbeds(name, runs, what = '6 ?embed= iframes') {
  console.log(`page: ${what}, cold, ${name.padEnd(22)} first numbers ${stat(runs.map((r) => r.first))}   all live ${stat(runs.map((r) => r.live))}`);
  console.log(`      Python runtimes (workers) started ${runs.map((r) => r.runtimes).join(', ')};  PSS of all Chromium processes ${stat(runs.map((r) => r.pssMB)).replace(/ ms/g, '')} MB (${runs[0].processes} processes)`);
}

/**
 * embedsRun RUNS times, each in a fresh profile on disk (a user's browser: HTTP cache and offline
 * cache on disk), each Chromium alone (another would share, and halve the PSS of, the binary's pages).
 */
async function freshProfiles(elements) {
  await browser.close();
  const runs = [];
  for (let i = 0; i < RUNS; i++) runs.push(await inFreshProfile(async (ctx, dir) => embedsRun(ctx, await ctx.newCDPSession(ctx.pages()[0]), dir, elements)));
  browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
  return runs;
}

/** `run(ctx, dir)` in a Chromium of its own with a new profile on disk (`dir`), removed after. */
async function inFreshProfile(run) {
  const dir = mkdtempSync(join(tmpdir(), 'pulab-bench-profile-'));
  const ctx = await chromium.launchPersistentContext(dir, { executablePath: CHROMIUM, args: CHROMIUM_ARGS, viewport: { width: 1366, height: 768 } });
  try {
    return await run(ctx, dir);
  } finally {
    await ctx.close();
    rmSync(dir, { recursive: true, force: true });
  }
}

if (SCEN.has('embeds')) {
  reportEmbeds('fresh profile on disk', await freshProfiles(false));
  // An incognito-like context (Playwright's default, the other scenarios): the browser keeps the
  // HTTP cache and the offline cache (≈ 45 MB of runtime files) in memory.
  const otr = [];
  for (let i = 0; i < RUNS; i++) {
    const ctx = await newCtx();
    otr.push(await embedsRun(ctx, await browser.newBrowserCDPSession(), MARK));
    await ctx.close();
  }
  reportEmbeds('incognito context', otr);
}

if (SCEN.has('panel')) {
  reportEmbeds('fresh profile on disk', await freshProfiles('one'), '1 <pu-lab-panel> (not the seed), other origin');
}
if (SCEN.has('elements')) {
  reportEmbeds('fresh profile on disk', await freshProfiles(true), '12 <pu-lab-panel>, other origin');
}

if (SCEN.has('input')) {
  // Two drivers, each in a fresh context: Playwright's fill (as measured from the start;
  // it also runs its actionability checks in the page, forcing layouts) and plain keyboard events
  // (select all, type the text: what a user's keyboard sends). 40 edits each, the first one 3 s
  // after the numbers went live; the first 10 and the rest are printed apart (the first ones after
  // a boot run slower: JIT and wasm tier-up on a 2-core machine).
  for (const driver of ['fill', 'keyboard']) {
    const ctx = await newCtx();
    const p = await ctx.newPage();
    await boot(p, url);
    await p.waitForTimeout(3000);
    const upd = [];
    const rep = [];
    const ren = [];
    const wrk = [];
    const slow = new Map();
    const field = 'input[name="motor.rs_ohm"]';
    if (driver === 'keyboard') await p.focus(field);
    for (let i = 0; i < 40; i++) {
      const before = await p.$eval('[data-key="current_pi.d.ki"]', (e) => e.dataset.value);
      const text = (1 + i / 20).toFixed(3);
      if (driver === 'fill') await p.fill(field, text);
      else {
        await p.keyboard.press('Control+A');
        await p.keyboard.insertText(text);
      }
      await p.waitForFunction((b) => document.querySelector('[data-key="current_pi.d.ki"]').dataset.value !== b, before, { polling: 5 });
      const d = await p.evaluate(() => ({ ...document.documentElement.dataset }));
      upd.push(Number(d.updateMs));
      rep.push(Number(d.reportMs));
      ren.push(Number(d.renderMs));
      wrk.push(Number(d.workerMs));
      for (const part of (d.renderSlowest ?? '').split(', ').filter(Boolean)) {
        const [id, ms] = part.split(' ');
        slow.set(id, [...(slow.get(id) ?? []), Number(ms)]);
      }
    }
    await ctx.close();
    const first = upd.slice(0, 10);
    const rest = upd.slice(10);
    console.log(`page: input → all numbers updated (${driver.padEnd(8)}) p50 ${q(upd, 0.5).toFixed(1)} ms, p95 ${q(upd, 0.95).toFixed(1)} ms   (target p95 ≤ 30); first 10 edits p50 ${q(first, 0.5).toFixed(1)} ms, the other 30 p50 ${q(rest, 0.5).toFixed(1)} / p95 ${q(rest, 0.95).toFixed(1)} ms`);
    console.log(`page:   report round trip to the worker  p50 ${q(rep, 0.5).toFixed(1)} ms, p95 ${q(rep, 0.95).toFixed(1)} ms  (in the worker: p50 ${q(wrk, 0.5).toFixed(1)} ms, p95 ${q(wrk, 0.95).toFixed(1)} ms)`);
    console.log(`page:   rendering the new report         p50 ${q(ren, 0.5).toFixed(1)} ms, p95 ${q(ren, 0.95).toFixed(1)} ms;  slowest panels (median ms when among the 3 slowest): ${[...slow].sort((a, b) => q(b[1], 0.5) - q(a[1], 0.5)).slice(0, 5).map(([id, v]) => `${id} ${q(v, 0.5).toFixed(1)}`).join(', ')}`);
  }
}
/** `pick(report)` of CPython's pulab for the input JSON `text` with R_s = each of `digits` Ω. */
function typingExpected(text, digits, pick) {
  const inputs = digits.map((d) => {
    // the report the page asks for: no simulation, no loop analysis
    const { sim: _s, analysis: _a, ...inp } = JSON.parse(text);
    inp.motor.rs_ohm = d;
    return inp;
  });
  const reports = JSON.parse(execFileSync('python3', ['-c', 'import json,sys; from pulab import report; print(json.dumps([report(i) for i in json.load(sys.stdin)]))'], {
    cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: JSON.stringify(inputs),
  }).toString());
  return reports.map(pick);
}

if (SCEN.has('typing')) {
  // Typing with the answer strip, Inovance and a non-Inovance firmware side by side: in a fresh
  // profile per run, the default page, the firmware picked in the strip, then keystrokes in R_s as
  // a user overtypes a value (select all, one digit: R_s = 2, 3, 4, 5, 1 Ω, twice). Each is timed
  // in the page from the key's event time to the DOM mutation that makes the numbers current:
  // <html data-numbers="live"> and the strip's integer that R_s moves equal to CPython's pulab.
  const DIGITS = [2, 3, 4, 5, 1, 2, 3, 4, 5, 1];
  const FIRMWARE = [['inovance', 'current_pi.d.pm_ki', (r) => r.current_pi.d.pm_ki], ['microchip', 'profiles.microchip.constants.KII.value', (r) => r.profiles.microchip.constants.KII.value]];
  const rows = [];
  for (const [fw, key, pick] of FIRMWARE) {
    let want = null;
    const loadBefore = loadavg()[0];
    const ms = [];
    const runMedians = [];
    const pageMs = [];
    for (let i = 0; i < RUNS; i++) {
      await inFreshProfile(async (ctx) => {
        const p = ctx.pages()[0] ?? await ctx.newPage();
        await boot(p, url);
        if (fw !== 'inovance') await p.selectOption('select[name="answer.profile"]', fw);
        await p.waitForSelector(`section.answer [data-key="${key}"][data-value]`, { timeout: 30_000 });
        await p.waitForFunction(isLive, null, { timeout: 30_000 });
        await p.waitForTimeout(3000); // the simulation runtime's boot and first run
        // The page's own input (its link), with each typed R_s, computed by CPython's pulab.
        want ??= typingExpected(await p.evaluate(() => decodeURIComponent(/[#&]in=([^&]*)/.exec(location.hash)[1])), DIGITS, pick);
        const field = 'input[name="motor.rs_ohm"]';
        await p.focus(field);
        const one = [];
        for (let k = 0; k < DIGITS.length; k++) {
          await p.keyboard.press('Control+A');
          await p.evaluate(([sel, w]) => {
            window.benchKey = new Promise((resolve, reject) => {
              let t0 = null;
              const current = () => document.documentElement.dataset.numbers === 'live'
                && JSON.parse(document.querySelector(sel)?.dataset.value ?? 'null') === w;
              const obs = new MutationObserver(() => {
                if (t0 === null || !current()) return;
                obs.disconnect();
                resolve(performance.now() - t0);
              });
              obs.observe(document.documentElement, { attributes: true, childList: true, subtree: true, characterData: true });
              window.addEventListener('keydown', (ev) => { t0 = ev.timeStamp; }, { once: true, capture: true });
              setTimeout(() => reject(new Error(`no current numbers for ${w} within 10 s`)), 10_000);
            });
          }, [`section.answer [data-key="${key}"]`, want[k]]);
          await p.keyboard.press(String(DIGITS[k]));
          one.push(await p.evaluate(() => window.benchKey));
          pageMs.push(Number(await p.evaluate(() => document.documentElement.dataset.updateMs)));
        }
        ms.push(...one);
        runMedians.push(q(one, 0.5));
      });
    }
    rows.push({ fw, ms, runMedians, pageMs, load: [loadBefore, loadavg()[0]] });
  }
  for (const r of rows) {
    console.log(`page: keystroke → numbers + answer strip current (${r.fw.padEnd(9)}) p50 ${q(r.ms, 0.5).toFixed(1)} ms, p95 ${q(r.ms, 0.95).toFixed(1)} ms over ${r.ms.length} keystrokes; run medians ${r.runMedians.map((x) => x.toFixed(1)).join(', ')} ms; the page's own updateMs p50 ${q(r.pageMs, 0.5).toFixed(1)} ms; load (1 min) ${r.load.map((x) => x.toFixed(2)).join(' → ')}`);
  }
}
await browser.close();
server.close();
nosnap.server.close();
elementsServer.close();
const load1 = loadavg();
console.log(`page: ${SETTLE ? 'each run navigated once its new browser window had settled' : 'each run navigated the moment its window existed (BENCH_SETTLE=0)'}`);
console.log(`page: load average before ${load0.map((x) => x.toFixed(2)).join(' ')}, after ${load1.map((x) => x.toFixed(2)).join(' ')} (2 cores; ${RUNS} runs per scenario)`);
