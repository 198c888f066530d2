// Docs pages built with the real tools from docs/deploy.md's snippets (tests/py/docs_samples.py:
// Sphinx directive, MkDocs fence, Doxygen \htmlonly, Confluence user macro), served from ANOTHER
// ORIGIN than pu-lab, whose server sends no CORS header (the classic embed.js tag needs none):
// with scripts off the Sphinx/MkDocs pages show the numbers pulab prerendered
// at build time; with scripts the panels go live (the oracle's numbers), the prerendered tables
// give way to the live panel, and every frame is sized to its content (the Confluence iframes by
// the macro's postMessage listener). Screenshots: tests/e2e/screenshots/docs-*.png.
import { createServer } from 'node:http';
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';

const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.css': 'text/css', '.json': 'application/json', '.png': 'image/png', '.svg': 'image/svg+xml', '.woff': 'font/woff', '.woff2': 'font/woff2', '.ttf': 'font/ttf' };

/** A plain static server of `dir` (the docs host: not pu-lab, no CSP of ours). */
function staticServer(dir) {
  const server = createServer((req, res) => {
    const path = normalize(join(dir, decodeURIComponent(new URL(req.url, 'http://x').pathname)));
    let file = path;
    try {
      if (statSync(file).isDirectory()) file = join(file, 'index.html');
      const body = readFileSync(file);
      res.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream' }).end(body);
    } catch {
      res.writeHead(req.url === '/favicon.ico' ? 204 : 404).end();
    }
  });
  return new Promise((r) => server.listen(0, '127.0.0.1', () => r({ server, url: `http://127.0.0.1:${server.address().port}/` })));
}

/** Every iframe's height equals its document's height (within 1 px), nothing to scroll inside. */
async function framesFit(page, assert, site) {
  const frames = page.frames().filter((f) => f.url().startsWith(site));
  assert(frames.length > 0, 'no panel frames');
  for (const f of frames) {
    const fits = () => Math.abs(document.documentElement.scrollHeight - window.innerHeight) <= 1 && window.innerHeight > 40
      && document.documentElement.scrollWidth <= window.innerWidth;
    const ok = await f.waitForFunction(fits, null, { timeout: 5000, polling: 50 }).then(() => true, () => false);
    const inner = await f.evaluate(() => `${document.documentElement.scrollHeight}×${document.documentElement.scrollWidth} px in ${window.innerHeight}×${window.innerWidth} px`);
    assert(ok, `${new URL(f.url()).search}: document ${inner}`);
  }
  return frames;
}

export default async function docsTools(ctx) {
  const { check, assert, newPage, golden, origins, ROOT, SHOTS } = ctx;
  const subSrv = await ctx.serve(ctx.SUB, { cors: false });
  const other = golden('04_ind380_7k5.json');
  const rpm = String(other.expected.vendor.Rpm.value);
  const out = mkdtempSync(join(tmpdir(), 'pulab-docs-'));
  const built = JSON.parse(execFileSync(join(ROOT, '.venv/bin/python'), [join(ROOT, 'tests/py/docs_samples.py'), out, subSrv.url], { cwd: ROOT }).toString());
  const host = await staticServer(out);
  origins.add(new URL(host.url).origin);
  const url = (tool) => host.url + built[tool].slice(out.length + 1);
  const allLive = (page, n) => page.waitForFunction((k) => document.querySelectorAll('pu-lab-panel[data-numbers="live"]').length === k, n, { timeout: 120_000, polling: 50 });
  const tools = ['sphinx', 'mkdocs', 'doxygen'].filter((t) => t in built);
  assert(tools.includes('doxygen') || !process.env.CI, 'doxygen missing under CI');
  try {
    for (const tool of ['sphinx', 'mkdocs']) {
      await check(`${tool}: with scripts off the page shows the prerendered numbers (oracle's Rpm ${rpm})`, async () => {
        const page = await newPage({ context: { javaScriptEnabled: false } });
        await page.goto(url(tool));
        const shown = await page.$eval('pu-lab-panel[panel="vendor"] [data-key="vendor.Rpm.value"]', (e) => ({ text: e.textContent, visible: e.checkVisibility() }));
        assert(shown.text === rpm && shown.visible, `Rpm shown ${JSON.stringify(shown)}`);
        await page.screenshot({ path: join(SHOTS, `docs-${tool}-noscript-1366.png`), fullPage: true });
        await page.context().close();
      });
    }
    for (const tool of tools) {
      await check(`${tool}: the panels go live from another origin (oracle's numbers), prerendered tables hidden, frames sized to content`, async () => {
        for (const [width, name] of [[1366, '1366'], [390, '390']]) {
          const page = await newPage({ context: { viewport: { width, height: 800 } } });
          await page.goto(url(tool));
          const n = await page.$$eval('pu-lab-panel', (e) => e.length);
          await allLive(page, n);
          const vendor = page.frames().find((f) => f.url().includes('embed=vendor'));
          const live = await vendor.$eval('[data-key="vendor.Rpm.value"][data-value]', (e) => e.dataset.value);
          assert(live === rpm, `live Rpm ${live}, oracle ${rpm}`);
          const shownTables = await page.$$eval('pu-lab-panel table', (t) => t.filter((e) => e.checkVisibility()).length);
          assert(shownTables === 0, `${shownTables} prerendered tables still shown`);
          await framesFit(page, assert, subSrv.url);
          await page.screenshot({ path: join(SHOTS, `docs-${tool}-${name}.png`), fullPage: true });
          // A full-page shot leaves frames below the fold unpainted: the last panel on its own.
          const last = (await page.$$('pu-lab-panel')).at(-1);
          await last.scrollIntoViewIfNeeded();
          await page.waitForTimeout(500);
          await last.screenshot({ path: join(SHOTS, `docs-${tool}-${name}-last.png`) });
          await page.context().close();
        }
      });
    }
    await check('confluence user macro: two plain iframes go live and take their content\'s height from the size messages', async () => {
      const page = await newPage();
      await page.goto(url('confluence'));
      const frames = () => page.frames().filter((f) => f.url().startsWith(subSrv.url));
      await page.waitForFunction(() => document.querySelectorAll('iframe.pu-lab-frame').length === 2);
      for (const f of frames()) await f.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 120_000, polling: 50 });
      const heights = await page.$$eval('iframe.pu-lab-frame', (fs) => fs.map((f) => f.getBoundingClientRect().height));
      assert(heights.every((h) => h !== 640), `heights still the template's 640 px: ${heights}`);
      await framesFit(page, assert, subSrv.url);
      const vendor = frames().find((f) => f.url().includes('embed=vendor'));
      assert(await vendor.$eval('[data-key="vendor.Rpm.value"][data-value]', (e) => e.dataset.value) === rpm, 'vendor frame not the 7.5 kW motor');
      await page.screenshot({ path: join(SHOTS, 'docs-confluence-1366.png'), fullPage: true });
      await page.context().close();
    });
    await check('Jupyter widget front end (pulab_docs/widget.js) with a stand-in anywidget model: the panel goes live and its report reaches the model', async () => {
      copyFileSync(join(ROOT, 'py/pulab_docs/widget.js'), join(out, 'widget.js'));
      // What anywidget gives render(): a model (get/set/save_changes/on/off) and an element.
      writeFileSync(join(out, 'notebook.html'), `<!doctype html><html><head><meta charset="utf-8"><title>notebook</title></head><body><div id="out"></div>
<script type="module">
import widget from './widget.js';
const state = { site: ${JSON.stringify(subSrv.url)}, panel: 'vendor', lang: 'en', input: ${JSON.stringify(other.input)}, report: {}, numbers: '' };
window.saved = [];
const model = { get: (k) => state[k], set: (k, v) => { state[k] = v; }, save_changes: () => window.saved.push(state.numbers), on() {}, off() {} };
window.state = state;
await widget.render({ model, el: document.getElementById('out') });
</script></body></html>`);
      const page = await newPage();
      await page.goto(`${host.url}notebook.html`);
      await page.waitForFunction(() => window.state?.numbers === 'live', null, { timeout: 120_000, polling: 50 });
      const got = await page.evaluate(() => window.state.report.vendor.Rpm.value);
      assert(String(got) === rpm, `model report Rpm ${got}, oracle ${rpm}`);
      assert(await page.$eval('pu-lab-panel', (e) => e.getAttribute('panel') === 'vendor' && JSON.parse(e.getAttribute('input')).motor.rated_voltage_v === 380), 'element attributes from the model');
      await page.context().close();
    });
    await check('oEmbed: a consumer discovers a panel\'s description from its page URL and embeds its HTML; the panel goes live', async () => {
      // `pulab oembed` writes into the deployed site (here dist/, removed afterwards).
      execFileSync(join(ROOT, '.venv/bin/python'), ['-m', 'pulab', 'oembed', subSrv.url, join(ROOT, 'dist'), '--input', '-', '--name', 'e2e', '--panel', 'vendor'], {
        cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: JSON.stringify(other.input),
      });
      try {
        const discovery = await (await fetch(`${subSrv.url}oembed/e2e/vendor.html`)).text();
        const href = /<link rel="alternate" type="application\/json\+oembed" href="([^"]+)"/.exec(discovery)?.[1];
        assert(href, 'no discovery link');
        const res = await fetch(href.replaceAll('&amp;', '&'));
        assert(res.ok && /json/.test(res.headers.get('content-type') ?? ''), `oEmbed JSON: ${res.status} ${res.headers.get('content-type')}`);
        const doc = await res.json();
        assert(doc.version === '1.0' && doc.type === 'rich' && doc.height > 0, JSON.stringify(doc));
        writeFileSync(join(out, 'wiki.html'), `<!doctype html><html><head><meta charset="utf-8"><title>wiki</title></head><body><h1>Wiki page</h1>${doc.html}</body></html>`);
        const page = await newPage();
        await page.goto(`${host.url}wiki.html`);
        const frame = () => page.frames().find((f) => f.url().startsWith(subSrv.url));
        await page.waitForFunction(() => document.querySelector('iframe') !== null);
        await frame().waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 120_000, polling: 50 });
        assert(await frame().$eval('[data-key="vendor.Rpm.value"][data-value]', (e) => e.dataset.value) === rpm, 'oEmbed frame not the 7.5 kW motor');
        await page.context().close();
      } finally {
        rmSync(join(ROOT, 'dist/oembed/e2e'), { recursive: true, force: true });
      }
    });
  } finally {
    host.server.close();
    rmSync(out, { recursive: true, force: true });
  }
}
