// <pu-lab-panel> (dist/embed.js) on a docs page of ANOTHER ORIGIN (the host on its own port):
// twelve elements go live, size their iframes to their content (no inner scrollbar), raise
// `pu-lab-report` with numbers the host text quotes (checked against the oracles' golden vectors),
// follow the host's dark scheme, and start at most two runtimes. Both forms of the tag: the module
// tag (`<script type="module" src>`, its server sends Access-Control-Allow-Origin) and the classic
// tag (`<script src>` in the host's head) from a pu-lab server sending NO CORS header — the same
// panels, numbers and events, and the host page fetches nothing from pu-lab but embed.js (no-cors).
// On a host of another SITE (http://localhost:PORT; the site is at 127.0.0.1) Chromium denies the
// frames a SharedWorker (third-party storage blocked): the panels still go live, each on a
// dedicated runtime. Screenshots: tests/e2e/screenshots/embed-*.png.
import { createServer } from 'node:http';
import { join } from 'node:path';
import { watchWorkers } from '../workers.mjs';

const PANELS = ['bases', 'pu', 'vendor', 'constants', 'current', 'pll', 'loop', 'qcalc', 'conventions', 'datasheet', 'review', 'vendors'];

/**
 * The host page: 12 elements (the odd ones with another motor), and text quoting their reports.
 * `classic`: embed.js by a classic tag, and the first element holds prerendered numbers (what the
 * docs builds put there), which the classic tag in the head must not miss.
 */
function hostPage(site, other, lang, panels = PANELS, classic = false) {
  const pre = (i) => (classic && i === 0 ? '<p class="pre">Rpm <span data-key="vendor.Rpm.value" data-value="0">0</span> (prerendered)</p>' : '');
  const els = panels.map((p, i) => `<h2>${p}</h2><p>Quoted: <span class="quote" data-for="${i}">…</span></p>
<pu-lab-panel id="p${i}" panel="${p}" lang="${lang}"${i % 2 ? ` input='${JSON.stringify(other)}'` : ''}>${pre(i)}</pu-lab-panel>`).join('\n');
  return `<!doctype html><html><head><meta charset="utf-8"><meta name="viewport" content="width=device-width">
<title>docs host</title><meta name="color-scheme" content="light dark">
<style>body{font-family:sans-serif;max-width:960px;margin:auto;padding:8px}@media (prefers-color-scheme: dark){body{background:#111;color:#ddd}}</style>
<script${classic ? '' : ' type="module"'} src="${site}embed.js"></script></head><body>
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
  const { check, assert, newPage, golden, browser, subSrv, origins, SHOTS, SUB, compareShown } = ctx;
  const seed = golden('01_seed_motor.json');
  const other = golden('04_ind380_7k5.json');
  let lang = 'en';
  // A pu-lab server whose headers the docs team cannot set: no Access-Control-Allow-Origin.
  const noCors = await ctx.serve(SUB, { cors: false });
  const host = await hostServer((u) => (u.startsWith('/two') ? hostPage(subSrv.url, other.input, lang, PANELS.slice(1, 3))
    : u.startsWith('/classic') ? hostPage(noCors.url, other.input, lang, PANELS, true) : hostPage(subSrv.url, other.input, lang)));
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

    await check('classic <script src="embed.js"> from a pu-lab server with no CORS header: 12 panels live, the same numbers and events, ≤ 2 runtimes', async () => {
      const head = await fetch(`${noCors.url}embed.js`);
      assert(head.ok && head.headers.get('access-control-allow-origin') === null, `embed.js: ${head.status}, ACAO ${head.headers.get('access-control-allow-origin')}`);
      assert((await fetch(`${subSrv.url}embed.js`)).headers.get('access-control-allow-origin') === '*', 'the module form\'s server sends no ACAO');
      const page = await newPage();
      const site = new URL(noCors.url).origin;
      const fromHost = [];
      page.on('request', (r) => {
        if (r.frame() === page.mainFrame() && new URL(r.url()).origin === site) fromHost.push(r.allHeaders().then((h) => [new URL(r.url()).pathname, h['sec-fetch-mode'], r.resourceType(), h.origin ?? null]));
      });
      const w = await watchWorkers(browser, page);
      await page.goto(`${host.url}classic`);
      await allLive(page);
      await page.waitForTimeout(1500); // a simulation runtime started late would be counted too
      const started = [...w.kinds];
      await w.stop();
      assert(!started.includes('worker'), `dedicated workers: ${started.join(',')}`);
      const shared = started.filter((k) => k === 'shared_worker').length;
      assert(shared >= 1 && shared <= 2, `runtimes: ${shared}`);
      // Only embed.js is fetched by the host page itself, as a classic script (no CORS request); the frames load the rest.
      const navs = (await Promise.all(fromHost)).filter(([, , t]) => t !== 'document');
      assert(navs.length === 1 && navs[0][0] === `${SUB}embed.js` && navs[0][1] === 'no-cors' && navs[0][2] === 'script' && navs[0][3] === null, `host page requests to pu-lab: ${JSON.stringify(navs)}`);
      // The same events and quoted numbers as the module form.
      const quotes = await page.$$eval('.quote', (q) => q.map((e) => e.textContent));
      quotes.forEach((q, i) => {
        const want = (i % 2 ? other : seed).expected.vendor.Rpm.value;
        assert(q === `${want} (live)`, `panel ${i} quoted ${q}, oracle ${want}`);
      });
      const reports = await page.evaluate(() => window.reports);
      assert(Object.keys(reports).length === PANELS.length && reports[3].panel === 'constants', 'one report event per element, naming its panel');
      // Every number each frame shows (data-key/data-value) is the oracle's for that element's motor.
      let n = 0;
      for (let i = 0; i < PANELS.length; i++) {
        const frame = await (await page.$(`#p${i} > iframe`)).contentFrame();
        assert(new URL(frame.url()).origin === site, `frame ${i} at ${frame.url()}`);
        n += await compareShown(frame, (i % 2 ? other : seed).expected);
      }
      assert(n > 50, `only ${n} numbers compared`);
      // The prerendered numbers inside the first element were seen (the tag is in the head) and give way to the live panel.
      assert(await page.$eval('#p0 > .pre', (e) => e.hidden), 'prerendered numbers not hidden once the panel is live');
      console.log(`      classic tag, no CORS header: ${n} numbers match the oracles; workers started: ${started.join(',')}`);
      await page.screenshot({ path: join(SHOTS, 'embed-host-classic-1366-en.png') });
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
