import { chromium } from 'playwright-core';
import { serve } from './serve.mjs';
const srv = await serve('/tmp/harden-dist', '/x/');
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--no-sandbox', '--disable-gpu'] });
for (const file of process.argv.slice(2)) {
  const ctx = await browser.newContext();
  const page = await ctx.newPage();
  page.on('pageerror', (e) => console.log('pageerror', e.message));
  const hits = [];
  await ctx.route(`**/pyodide/${file}`, (r) => { hits.push(r.request().url().slice(-40)); return r.fulfill({ status: 404, body: 'not found' }); });
  await page.goto(srv.url);
  for (let i = 0; i < 8; i++) {
    await page.waitForTimeout(5000);
    console.log(file, i * 5, await page.$eval('.status', (e) => e.textContent), hits.length);
  }
  await ctx.close();
}
await browser.close(); srv.server.close();
