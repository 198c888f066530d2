// <pu-lab-panel> (dist/embed.js) on a docs page of ANOTHER ORIGIN (the host on its own port):
// twelve elements go live, size their iframes to their content (no inner scrollbar), raise
// `pu-lab-report` with numbers the host text quotes (checked against the oracles' golden vectors),
// follow the host's dark scheme, and start at most two runtimes. On a host of another SITE
// (http://localhost:PORT; the site is at 127.0.0.1) Chromium denies the frames a SharedWorker
// (third-party storage blocked): the panels still go live, each on a dedicated runtime.
// Screenshots: tests/e2e/screenshots/embed-*.png.
import { createServer } from 'node:http';
import { join } from 'node:path';
import { watchWorkers } from '../workers.mjs';

const PANELS = ['bases', 'pu', 'vendor', 'constants', 'current', 'pll', 'loop', 'qcalc', 'conventions', 'datasheet', 'review', 'vendors'];

/** The host page: 12 elements (the odd ones with another motor), and text quoting their reports. */
function hostPage(site, other, lang, panels = PANELS) {
  const els = panels.map((p, i) => `<h2>${p}</h2><p>Quoted: <span class="quote" data-for="${i}">…</span></p>
<pu-lab-panel id="p${i}" panel="${p}" lang="${lang}"${i % 2 ? ` input='${JSON.stringify(other)}'` : ''}></pu-lab-panel>`).join('\n');
  return `<!doctype html><html><head><meta charset="utf-8"><meta name="viewport" content="width=device-width">
<title>docs host</title><meta name="color-scheme" content="light dark">
<style>body{font-family:sans-serif;max-width:960px;margin:auto;padding:8px}@media (prefers-color-scheme: dark){body{background:#111;color:#ddd}}</style>
<script type="module" src="${site}embed.js"></script></head><body>
<h1>Motor notes</h1>
<script>
window.reports = {};
document.addEventListener('pu-lab-report', (ev) => {
  const i = ev.target.id.slice(1);
  window.reports[i] = ev.detail;
  document.querySelector('.quote[data-for="' + i + '"]').textContent = ev.detail.report.vendor.Rpm.value + ' (' + ev.detail.numbers + ')';
});
</script>
${els}
</body></html>`;
}

/** A plain server for the host page only (the host is not pu-lab: no CSP of ours). */
function hostServer(html) {
  const server = createServer((req, res) => res.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8' }).end(html(req.url)));
  const at = (name) => `http://${name}:${server.address().port}/`;
  return new Promise((r) => server.listen(0, '127.0.0.1', () => r({ server, url: at('127.0.0.1'), crossSite: at('localhost') })));
}

export default async function embed(ctx) {
  const { check, assert, newPage, golden, browser, subSrv, origins, SHOTS } = ctx;
  const seed = golden('01_seed_motor.json');
  const other = golden('04_ind380_7k5.json');
  let lang = 'en';
  const host = await hostServer((u) => (u.startsWith('/two') ? hostPage(subSrv.url, other.input, lang, PANELS.slice(1, 3)) : hostPage(subSrv.url, other.input, lang)));
  origins.add(new URL(host.url).origin);
  origins.add(new URL(host.crossSite).origin);
  const allLive = (page, n = PANELS.length) => page.waitForFunction((k) => document.querySelectorAll('pu-lab-panel[data-numbers="live"]').length === k, n, { timeout: 120_000, polling: 50 });

  try {
    await check('12 <pu-lab-panel> on a page of another origin: all live, sized to content, quoted by the host, ≤ 2 runtimes', async () => {
      const page = await newPage();
      const w = await watchWorkers(browser, page);
      const t0 = Date.now();
      await page.goto(host.url);
      await allLive(page);
      const ms = Date.now() - t0;
      await page.waitForTimeout(1500); // a simulation runtime started late would be counted too
      const started = [...w.kinds];
      await w.stop();
      console.log(`      12 panels all live in ${ms} ms; workers started: ${started.join(',')}`);
      assert(!started.includes('worker'), `dedicated workers: ${started.join(',')}`);
      const shared = started.filter((k) => k === 'shared_worker').length;
      assert(shared >= 1 && shared <= 2, `runtimes: ${shared}`);
      // The host's text quotes each panel's report: the oracle's number for that panel's motor.
      const quotes = await page.$$eval('.quote', (q) => q.map((e) => e.textContent));
      quotes.forEach((q, i) => {
        const want = (i % 2 ? other : seed).expected.vendor.Rpm.value;
        assert(q === `${want} (live)`, `panel ${i} quoted ${q}, oracle ${want}`);
      });
      const reports = await page.evaluate(() => window.reports);
      assert(Object.keys(reports).length === PANELS.length && reports[3].panel === 'constants', 'one report event per element, naming its panel');
      // Sized to content: each iframe's height is its document's height, nothing to scroll inside.
      for (const f of page.frames().filter((f) => f !== page.mainFrame())) {
        // Within 1 px: a sub-pixel height (633.5 px) rounds either way in scrollHeight.
        const fits = () => Math.abs(document.documentElement.scrollHeight - window.innerHeight) <= 1
          && document.documentElement.scrollWidth <= window.innerWidth && window.innerHeight > 40;
        // The last size message may still be on its way (a panel drawing a plot after "live").
        const ok = await f.waitForFunction(fits, null, { timeout: 5000, polling: 50 }).then(() => true, () => false);
        const inner = await f.evaluate(() => ({ doc: document.documentElement.scrollHeight, view: window.innerHeight, w: document.documentElement.scrollWidth, vw: window.innerWidth }));
        assert(ok, `${new URL(f.url()).search}: document ${inner.doc}×${inner.w} px in a ${inner.view}×${inner.vw} px iframe`);
      }
      await page.screenshot({ path: join(SHOTS, 'embed-host-1366-en.png') });
      await page.context().close();
    });

    await check('on a host of another site (third-party frames, SharedWorker denied): the panels go live on dedicated runtimes', async () => {
      const page = await newPage();
      await page.goto(`${host.crossSite}two`);
      await allLive(page, 2);
      const kinds = await Promise.all(page.frames().filter((f) => f !== page.mainFrame()).map((f) => f.evaluate(() => document.documentElement.dataset.runtime)));
      console.log(`      cross-site runtimes: ${kinds.join(',')}`);
      const quotes = await page.$$eval('.quote', (q) => q.map((e) => e.textContent));
      assert(quotes[0] === `${seed.expected.vendor.Rpm.value} (live)` && quotes[1] === `${other.expected.vendor.Rpm.value} (live)`, `quotes ${quotes}`);
      await page.context().close();
    });

    await check('the host\'s dark scheme reaches the panels (prefers-color-scheme, then the theme attribute), 390 px zh', async () => {
      lang = 'zh';
      const page = await newPage({ context: { colorScheme: 'dark', viewport: { width: 390, height: 800 } } });
      await page.goto(host.url);
      await allLive(page);
      const frame = () => page.frames().find((f) => f.url().includes('embed=vendor'));
      assert(await frame().evaluate(() => document.documentElement.dataset.theme) === 'dark', 'frame not dark');
      assert(await frame().evaluate(() => document.documentElement.lang) === 'zh-CN', 'lang attribute not followed');
      await page.screenshot({ path: join(SHOTS, 'embed-host-390-zh-dark.png') });
      const before = frame().url();
      await page.$eval('#p2', (e) => e.setAttribute('theme', 'light'));
      await frame().waitForFunction(() => document.documentElement.dataset.theme === 'light', null, { timeout: 5000 });
      assert(frame().url() === before, 'a theme change reloaded the panel');
      await page.context().close();
      lang = 'en';
    });
  } finally {
    host.server.close();
  }
}
