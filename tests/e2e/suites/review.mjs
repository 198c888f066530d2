// Datasheet entry, the graded design review, input handling, every screen.
// Run alone: node tests/e2e/run.mjs review   (E2E_NO_BUILD=1 to reuse dist/)
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

const VIEWPORTS = [390, 900, 1366];

export default async function review(ctx) {
  const { check, assert, newPage, subSrv, ready, valueOf, waitValue, cpython, compareShown, ROOT, SHOTS } = ctx;
  const srp = JSON.parse(readFileSync(join(ROOT, 'tests/golden/review/heidenhain_srp5000.json'), 'utf8'));
  const link = (inp) => `${subSrv.url}#in=${encodeURIComponent(JSON.stringify(inp))}`;
  const page = await newPage();

  await check('review: a datasheet link (HEIDENHAIN SRP 5000) gives the numbers CPython gives, conversions shown', async () => {
    const inp = { ...srp.input, conventions: { base: 'rms' } };
    const want = cpython(inp);
    await page.goto(link(inp));
    await ready(page);
    await waitValue(page, 'datasheet.conversions.1.value', want.datasheet.conversions[1].value);
    const n = await compareShown(page, want);
    assert(n >= 80, `only ${n} numbers compared`);
    const formulas = await page.$$eval('.panel-datasheet code.formula', (els) => els.map((e) => e.textContent));
    assert(formulas.some((f) => f.includes('E_LL = Ke·2π·n/60 = 0.397·2π·300/60')), formulas.join(' | '));
    // the motor fields a datasheet sets are empty, their placeholder the derived value
    const ph = await page.getAttribute('input[name="motor.bemf_v"]', 'placeholder');
    assert(ph === '= 12.472123', `placeholder ${ph}`);
    assert((await valueOf(page, 'mechanical.rated_speed_rpm')) === 300, 'rated speed');
  });

  await check('review: findings at the top and at the value concerned; counts equal CPython', async () => {
    const want = cpython(srp.input).review;
    // The banner on top carries errors and warnings; with notes only (this drive) it stays empty.
    const top = await page.textContent('.warnings');
    const serious = want.counts.error + want.counts.warning;
    assert(serious ? top.includes(`${want.counts.error} errors, ${want.counts.warning} warnings`) : top.trim() === '', top);
    const sev = await page.getAttribute('[data-key="vendor.pm_maxout_vol.value"]', 'data-finding-sev');
    assert(sev === 'note', `pm_maxout_vol marked ${sev}`);
    const items = await page.$$eval('.panel-review li.finding', (els) => els.map((e) => e.dataset.finding));
    assert(items.length === want.findings.length, `${items.length} findings shown, ${want.findings.length} in the report`);
  });

  await check('review: "both given" names the datasheet field, shown at it', async () => {
    await page.fill('input[name="motor.rated_freq_hz"]', '50');
    await page.waitForFunction(() => /motor\.rated_freq_hz/.test(document.querySelector('[data-err-for="datasheet.speed_rpm"]')?.textContent ?? ''), null, { timeout: 10_000 });
    assert(await page.$eval('main.panels', (e) => e.classList.contains('stale')), 'panels not marked stale');
    await page.fill('input[name="motor.rated_freq_hz"]', '');
    await page.waitForFunction(() => !document.querySelector('main.panels')?.classList.contains('stale'), null, { timeout: 10_000 });
  });

  await check('review: Voltage = 70000 → a limit of the Inovance firmware at its panel, not an input error', async () => {
    await page.goto(link(ctx.golden('01_seed_motor.json').input));
    await ready(page);
    await page.fill('input[name="motor.rated_voltage_v"]', '70000');
    await page.waitForSelector('#panel-vendor .firmware-limits [data-field="raw.Voltage"]', { timeout: 30_000 });
    assert(!(await page.$eval('main.panels', (e) => e.classList.contains('stale'))), 'marked stale');
    assert((await page.textContent('[data-err-for="motor.rated_voltage_v"]').catch(() => '')) === '', 'an input error');
    await waitValue(page, 'base.U_b', 70000 / Math.sqrt(3));
    // full-width digits from a Chinese IME
    await page.fill('input[name="motor.rated_voltage_v"]', '２２０');
    await waitValue(page, 'vendor.raw.Voltage', 220);
    assert(!(await page.$eval('main.panels', (e) => e.classList.contains('stale'))), 'still stale');
    await page.fill('input[name="motor.rated_voltage_v"]', '17');
    await waitValue(page, 'vendor.raw.Voltage', 17);
  });

  await check('review: Q calculator reads 0x8000, 40000 as Q15 and iq24', async () => {
    await page.$eval('#panel-qcalc', (e) => e.scrollIntoView()); // its view (Tools) shown
    await page.selectOption('select[name="qcalc.mode"]', 'decode');
    await page.fill('input[name="qcalc.format"]', 'Q15');
    await page.fill('input[name="qcalc.raw"]', '0x8000');
    await waitValue(page, 'qcalc.result.raw', -32768);
    await page.fill('input[name="qcalc.raw"]', '40000');
    await waitValue(page, 'qcalc.result.value', -0.779296875);
    await page.fill('input[name="qcalc.format"]', '_IQ24');
    await page.fill('input[name="qcalc.raw"]', '0x01000000');
    await waitValue(page, 'qcalc.result.value', 1);
  });

  await check('review: share link keeps display units and shortest decimals', async () => {
    await page.selectOption('select[data-unit-for="motor.ld_h"]', 'mH');
    await page.fill('input[name="motor.ld_h"]', '4.2');
    await waitValue(page, 'vendor.raw.LD', 420);
    await page.click('button.copy-link');
    const url = await page.waitForFunction(() => document.documentElement.dataset.shareLink).then((h) => h.jsonValue());
    const hash = decodeURIComponent(url.split('#')[1]);
    assert(hash.includes('"ld_h":0.0042,') && !hash.includes('0.004200000000000001'), hash);
    assert(/u=\{[^}]*"motor\.ld_h":"mH"/.test(hash), `units not in link: ${hash}`);
    const p2 = await newPage();
    await p2.goto(url);
    await ready(p2);
    assert((await p2.inputValue('input[name="motor.ld_h"]')) === '4.2', 'unit lost on opening the link');
    await p2.context().close();
  });

  await check('review: JSON export holds the simulation metrics; CSV headers carry units', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-pll', (e) => e.scrollIntoView()); // simulations run for visible plots
    await page.waitForSelector('[data-key="sim.pll.metrics.q15.steady_angle_error_deg"][data-value]', { timeout: 60_000, state: 'attached' });
    const grab = async (kind) => {
      if (!(await page.$eval('details.export', (e) => e.open))) await page.click('.export > summary');
      const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`button[data-export="${kind}"]`)]);
      return readFileSync(await dl.path(), 'utf8');
    };
    const json = JSON.parse(await grab('json'));
    assert(typeof json.sim?.pll?.metrics?.q15?.steady_angle_error_deg === 'number', 'no sim metrics in the JSON export');
    assert(Array.isArray(json.review?.findings), 'no review in the JSON export');
    const csv = await grab('csv_pll');
    assert(csv.startsWith('t_s,si.theta_rad,'), csv.slice(0, 80));
  });

  await check('review: each data-key appears once per embed', async () => {
    const p = await newPage();
    for (const id of ['review', 'datasheet', 'bases', 'pu', 'vendor', 'constants', 'current', 'pll', 'qcalc']) {
      await p.goto(`${subSrv.url}?embed=${id}${id === 'datasheet' ? `#in=${encodeURIComponent(JSON.stringify(srp.input))}` : ''}`);
      await p.waitForSelector(`.panel-${id} [data-key][data-value]`, { timeout: 60_000 });
      if (id === 'current' || id === 'pll') await p.waitForSelector(`.panel-${id} table.metrics [data-value]`, { timeout: 60_000 });
      const keys = await p.$$eval('[data-key]', (els) => els.map((e) => e.dataset.key));
      const dup = keys.filter((k, i) => keys.indexOf(k) !== i);
      assert(dup.length === 0, `?embed=${id}: ${[...new Set(dup)].slice(0, 5).join(', ')} rendered twice`);
    }
    await p.context().close();
  });

  await check('review: ?embed=docs&chapter=…&anchor=… scrolls the iframe, never its host page', async () => {
    const p = await newPage();
    const src = `${subSrv.url}?embed=docs&chapter=03-pll&anchor=angle-base`;
    await p.setContent(`<div style="height:1500px">host top</div><iframe src="${src}" style="width:900px;height:500px"></iframe><div style="height:3000px"></div>`);
    const frame = await (await p.waitForSelector('iframe')).contentFrame();
    await frame.waitForSelector('[data-anchor="angle-base"]', { timeout: 60_000 });
    await p.waitForTimeout(500);
    assert((await p.evaluate(() => window.scrollY)) === 0, 'the host page scrolled');
    assert((await frame.evaluate(() => window.scrollY)) > 100, 'the iframe did not scroll to the anchor');
    await p.context().close();
  });

  for (const lang of ['en', 'zh']) {
    for (const width of VIEWPORTS) {
      await check(`review: usable at ${width} px (${lang}): no page-wide overflow, header clean, trace readable`, async () => {
        const p = await newPage({ context: { viewport: { width, height: 900 } } });
        await p.goto(`${subSrv.url}?lang=${lang}`);
        await ready(p);
        const m = await p.evaluate(() => {
          const hd = document.querySelector('header.top').getBoundingClientRect();
          const kids = [...document.querySelectorAll('header.top > *')].map((e) => e.getBoundingClientRect());
          const overlap = kids.some((a, i) => kids.some((b, j) => j > i && a.left < b.right - 1 && b.left < a.right - 1 && a.top < b.bottom - 1 && b.top < a.bottom - 1));
          const code = document.querySelector('table.trace td.code');
          const unit = document.querySelector('select[data-unit-for="drive.ts_s"]');
          return { page: document.documentElement.scrollWidth, win: window.innerWidth, headerH: hd.height, overlap,
            codeW: code.getBoundingClientRect().width, unitFits: unit.scrollWidth <= unit.clientWidth + 1 };
        });
        assert(m.page <= m.win, `page ${m.page} px wider than the window ${m.win} px`);
        assert(!m.overlap, 'header items overlap');
        assert(m.codeW >= 150, `C trace column only ${m.codeW} px wide`);
        // Narrow screens: the inputs are a drawer, one tap away.
        if (width < 1000) {
          await p.click('nav.tabs .inputs-toggle');
          await p.waitForTimeout(250);
        }
        await p.selectOption('select[data-unit-for="drive.ts_s"]', 'kHz');
        // the selected option's text, measured in the select's font, fits beside the arrow
        const fits = await p.$eval('select[data-unit-for="drive.ts_s"]', (u) => {
          const c = document.createElement('canvas').getContext('2d');
          const cs = getComputedStyle(u);
          c.font = `${cs.fontSize} ${cs.fontFamily}`;
          return c.measureText(u.selectedOptions[0].textContent).width <= u.clientWidth - 20;
        });
        assert(fits, 'Ts unit choice cut');
        if (width < 1000) await p.keyboard.press('Escape');
        await p.screenshot({ path: join(SHOTS, `review-${width}-${lang}-top.png`) });
        await p.$eval('#panel-vendor', (e) => e.scrollIntoView());
        await p.screenshot({ path: join(SHOTS, `review-${width}-${lang}-vendor.png`) });
        await p.$eval('#panel-review', (e) => e.scrollIntoView());
        await p.screenshot({ path: join(SHOTS, `review-${width}-${lang}-review.png`) });
        if (lang === 'zh') {
          const txt = await p.textContent('main.panels');
          for (const s of ['(seed ', '(drive)', '(rms)']) assert(!txt.includes(s), `untranslated "${s}" in zh`);
        }
        await p.context().close();
      });
    }
  }
  await page.context().close();
}
