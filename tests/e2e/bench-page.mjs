// `npm run bench`, page side (issue 4 targets; prints numbers, not a test): in headless Chromium,
// navigation → first numbers (cold, fresh context each run) and input change → every number
// updated (in-page, input event → last panel rendered), on the built dist/.
import { existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { serve } from './serve.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';
if (!existsSync(CHROMIUM)) {
  console.log(`page bench SKIPPED (no chromium at ${CHROMIUM})`);
  process.exit(0);
}
const { chromium } = await import('playwright-core');
execFileSync('npx', ['vite', 'build', '--config', 'web/vite.config.ts', '--logLevel', 'error'], { cwd: ROOT, stdio: 'inherit' });
const { server, url } = await serve(join(ROOT, 'dist'), '/bench/');
const browser = await chromium.launch({ executablePath: CHROMIUM, args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking', '--no-first-run'] });
const q = (a, f) => [...a].sort((x, y) => x - y)[Math.min(a.length - 1, Math.floor(f * a.length))];

const first = [];
const boots = [];
for (let i = 0; i < 3; i++) {
  const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
  const p = await ctx.newPage();
  const t0 = Date.now();
  await p.goto(url);
  await p.waitForSelector('[data-key="vendor.Rpm.value"][data-value]', { timeout: 60_000 });
  first.push(Date.now() - t0);
  boots.push(Number(await p.evaluate(() => document.documentElement.dataset.bootMs)));
  await ctx.close();
}
const ctx = await browser.newContext({ viewport: { width: 1366, height: 768 } });
const p = await ctx.newPage();
await p.goto(url);
await p.waitForSelector('[data-key="vendor.Rpm.value"][data-value]', { timeout: 60_000 });
await p.waitForTimeout(5000);
const upd = [];
const rep = [];
for (let i = 0; i < 40; i++) {
  const before = await p.$eval('[data-key="current_pi.d.ki"]', (e) => e.dataset.value);
  await p.fill('input[name="motor.rs_ohm"]', (1 + i / 20).toFixed(3));
  await p.waitForFunction((b) => document.querySelector('[data-key="current_pi.d.ki"]').dataset.value !== b, before, { polling: 5 });
  const d = await p.evaluate(() => ({ ...document.documentElement.dataset }));
  upd.push(Number(d.updateMs));
  rep.push(Number(d.reportMs));
}
await browser.close();
server.close();
console.log('');
console.log(`page: navigation → first numbers (cold)  ${first.join(', ')} ms   (target < 3000; Pyodide boot in the worker ${boots.join(', ')} ms)`);
console.log(`page: input → all numbers updated        p50 ${q(upd, 0.5).toFixed(1)} ms, p95 ${q(upd, 0.95).toFixed(1)} ms   (target p95 < 50)`);
console.log(`page: report round trip to the worker    p50 ${q(rep, 0.5).toFixed(1)} ms, p95 ${q(rep, 0.95).toFixed(1)} ms`);
