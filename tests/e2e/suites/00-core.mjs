// The page's core checks: golden numbers, typing, errors, share links, language,
// embed, explainer, Q calculator, units and presets, exports, the site root.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function core(ctx) {
  const { check, assert, newPage, compareShown, golden, cpython, cpythonMany, ready, valueOf, waitValue, subSrv, rootSrv, SHOTS, timings } = ctx;
  const seed = golden('01_seed_motor.json');
  const page = await newPage();
  await check('default page (served from a sub-path) shows the seed motor\'s golden numbers', async () => {
    const t0 = Date.now();
    await page.goto(subSrv.url);
    await page.waitForSelector('.status', { timeout: 5000 });
    timings.readable_ms = Date.now() - t0;
    await ready(page);
    timings.first_numbers_ms = Date.now() - t0;
    const n = await compareShown(page, seed.expected);
    assert(n >= 60, `only ${n} golden numbers found on the page`);
    assert((await valueOf(page, 'vendor.Rpm.value')) === 15022, 'Rpm');
    assert((await valueOf(page, 'vendor.Rpm')) === 15022, 'alias vendor.Rpm');
    console.log(`      ${n} numbers equal tests/golden/01_seed_motor.json`);
    await page.screenshot({ path: join(SHOTS, '01-default.png') });
    await page.$eval('#panel-vendor', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, '02-vendor.png') });
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-current .plot-host .main-svg', { timeout: 30_000 }); // drawn when visible
    await page.waitForTimeout(300);
    await page.screenshot({ path: join(SHOTS, '03-current.png') });
    await page.$eval('#panel-pll', (e) => e.scrollIntoView());
    await page.waitForSelector('.panel-pll .plot-host .main-svg', { timeout: 30_000 });
    await page.screenshot({ path: join(SHOTS, '04-pll.png') });
    await page.$eval('#panel-qcalc', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, '05-qcalc-conventions.png') });
  });

  await check('typing changes the numbers (equal to CPython pulab)', async () => {
    const input = { ...seed.input, motor: { ...seed.input.motor, rs_ohm: 3.3, ld_h: 0.00125 } };
    const want = cpython(input);
    await page.fill('input[name="motor.rs_ohm"]', '3.3');
    await page.fill('input[name="motor.ld_h"]', '1250'); // µH
    await waitValue(page, 'vendor.LD.value', want.vendor.LD.value);
    await waitValue(page, 'vendor.Rpm.value', want.vendor.Rpm.value);
    const n = await compareShown(page, want);
    assert(n >= 60, `only ${n}`);
    // latency: input event → all numbers updated
    const lat = [];
    const inPage = [];
    const rss = Array.from({ length: 20 }, (_, i) => (1 + i / 10).toFixed(2));
    const wants = cpythonMany(rss.map((rs) => ({ ...input, motor: { ...input.motor, rs_ohm: Number(rs) } })));
    await page.waitForTimeout(1500); // let the simulation worker finish booting (2 cores here)
    for (let i = 0; i < 20; i++) {
      const rs = rss[i];
      const w = wants[i];
      const t0 = Date.now();
      await page.fill('input[name="motor.rs_ohm"]', rs);
      await waitValue(page, 'current_pi.d.ki', w.current_pi.d.ki, 1e-9);
      lat.push(Date.now() - t0);
      inPage.push(Number(await page.evaluate(() => document.documentElement.dataset.updateMs)));
    }
    const q = (a, f) => [...a].sort((x, y) => x - y)[Math.min(a.length - 1, Math.floor(f * a.length))];
    // in-page: input event → every panel re-rendered; driver: fill() → number seen by the test
    timings.update_in_page_p50_ms = q(inPage, 0.5);
    timings.update_in_page_p95_ms = q(inPage, 0.95);
    timings.update_via_driver_p95_ms = q(lat, 0.95);
    timings.boot_ms = Number(await page.evaluate(() => document.documentElement.dataset.bootMs));
    timings.python_report_ms = Number(await page.evaluate(() => document.documentElement.dataset.reportMs));
  });

  await check('invalid input: message at the field, results marked stale, then recovers', async () => {
    await page.fill('input[name="motor.rs_ohm"]', 'abc');
    await page.waitForSelector('[data-err-for="motor.rs_ohm"]:not(:empty)');
    assert(await page.$eval('main.panels', (e) => e.classList.contains('stale')), 'not stale after a local error');
    await page.fill('input[name="motor.rs_ohm"]', '-1');
    await page.waitForFunction(() => /> 0/.test(document.querySelector('[data-err-for="motor.rs_ohm"]')?.textContent ?? ''), null, { timeout: 5000 });
    assert(await page.$eval('main.panels', (e) => e.classList.contains('stale')), 'not stale after a Python error');
    await page.$eval('#panel-bases', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, '06-invalid.png') });
    await page.fill('input[name="motor.rs_ohm"]', '1.5');
    await page.fill('input[name="motor.ld_h"]', '600');
    await waitValue(page, 'vendor.Rpm.value', 15022);
    await page.waitForFunction(() => !document.querySelector('main.panels').classList.contains('stale'));
    assert((await page.$eval('[data-err-for="motor.rs_ohm"]', (e) => e.textContent)) === '', 'error not cleared');
  });

  await check('a share link reproduces a state (golden 04, industrial 380 V)', async () => {
    const g = golden('04_ind380_7k5.json');
    const link = `${subSrv.url}#in=${encodeURIComponent(JSON.stringify(g.input))}`;
    const p2 = await newPage();
    await p2.goto(link);
    await ready(p2);
    await waitValue(p2, 'vendor.Rpm.value', g.expected.vendor.Rpm.value);
    const n = await compareShown(p2, g.expected);
    assert(n >= 60, `only ${n}`);
    assert((await p2.inputValue('input[name="motor.rated_voltage_v"]')) === '380', 'form not filled from the link');
    await p2.context().close();
  });

  await check('copy-link button → the link opens the same state', async () => {
    await page.fill('input[name="motor.rated_current_a"]', '2.5');
    await waitValue(page, 'vendor.raw.Current', 250);
    await page.click('button.copy-link');
    const url = await page.waitForFunction(() => document.documentElement.dataset.shareLink).then((h) => h.jsonValue());
    assert(url.startsWith(subSrv.url) && url.includes('#in='), `bad link ${url}`);
    const rpm = await valueOf(page, 'vendor.Rpm.value');
    const p2 = await newPage();
    await p2.goto(url);
    await ready(p2);
    await waitValue(p2, 'vendor.Rpm.value', rpm);
    await p2.context().close();
    // localStorage: a fresh visit without a hash restores the last input
    const p3 = await page.context().newPage();
    await p3.goto(subSrv.url);
    await ready(p3);
    await waitValue(p3, 'vendor.raw.Current', 250);
    await p3.close();
    await page.fill('input[name="motor.rated_current_a"]', '1.5');
    await waitValue(page, 'vendor.Rpm.value', 15022);
  });

  await check('language switch (zh ⇄ en), and zh default from the browser language', async () => {
    await page.click('button[data-lang="zh"]');
    await page.waitForFunction(() => document.documentElement.lang === 'zh-CN');
    const txt = await page.textContent('header.top');
    assert(/标幺/.test(txt), 'header not Chinese');
    assert(/额定电压/.test(await page.textContent('aside.inputs')), 'labels not Chinese');
    assert((await valueOf(page, 'vendor.Rpm.value')) === 15022, 'numbers lost');
    // the seed motor's review in Chinese (24 V bus: pm_maxout_vol in whole volts, the vendor's cost)
    assert(/厂商代码的性质/.test(await page.textContent('.panel-review')), 'review not Chinese');
    await page.$eval('#panel-vendor', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, '07-zh.png') });
    await page.click('button[data-lang="en"]');
    await page.waitForFunction(() => document.documentElement.lang === 'en');
    const zhPage = await newPage({ locale: 'zh-CN' });
    await zhPage.goto(subSrv.url);
    await zhPage.waitForFunction(() => document.documentElement.lang === 'zh-CN', null, { timeout: 10_000 });
    await zhPage.context().close();
  });

  await check('embed mode ?embed=vendor: one panel, no chrome', async () => {
    const p2 = await newPage();
    await p2.setViewportSize({ width: 900, height: 600 });
    await p2.goto(`${subSrv.url}?embed=vendor`);
    await ready(p2);
    assert((await p2.$$('section.panel')).length === 1, 'more than one panel');
    assert((await p2.$('header.top')) === null, 'header shown');
    assert(!(await p2.isVisible('aside.inputs')), 'inputs shown');
    await compareShown(p2, seed.expected);
    await p2.screenshot({ path: join(SHOTS, '08-embed-vendor.png') });
    await p2.goto(`${subSrv.url}?embed=current#in=${encodeURIComponent(JSON.stringify(golden('04_ind380_7k5.json').input))}`);
    await waitValue(p2, 'current_pi.d.pm_kp', golden('04_ind380_7k5.json').expected.current_pi.d.pm_kp, 0, 60_000);
    await p2.context().close();
  });

  await check('explainer: why? opens the chapter with the reader\'s numbers', async () => {
    const has = await page.$('#panel-vendor a.why');
    if (!has) return console.log('      (no docs/index.json: skipped)');
    await page.click('#panel-vendor a.why');
    await page.waitForSelector('article.doc [data-key="vendor.raw.Voltage"][data-value]', { timeout: 10_000 });
    assert((await page.$eval('article.doc [data-key="vendor.raw.Voltage"]', (e) => JSON.parse(e.dataset.value))) === 17, 'placeholder');
    // {{panel:inputs}} in chapter 1: the reader's inputs as Python normalized them.
    assert((await page.$eval('article.doc .doc-inputs [data-key="input.motor.rs_ohm"]', (e) => JSON.parse(e.dataset.value))) === 1.5, 'inputs embed');
    const katexErrors = await page.$$eval('article.doc .katex-error', (e) => e.length);
    assert(katexErrors === 0, `${katexErrors} KaTeX errors`);
    await page.waitForTimeout(300);
    await page.screenshot({ path: join(SHOTS, '09-docs.png') });
    assert(!page.url().includes('#doc-') && page.url().includes('#in='), 'the state hash was replaced');
  });

  await check('Q-format calculator answers from Python', async () => {
    await page.$eval('#panel-qcalc', (e) => e.scrollIntoView());
    await page.selectOption('select[name="qcalc.mode"]', 'encode');
    await page.fill('input[name="qcalc.format"]', 'Q0.15');
    await page.fill('input[name="qcalc.value"]', '0.5');
    await waitValue(page, 'qcalc.result.raw', 16384);
    await page.fill('input[name="qcalc.value"]', '1.5');
    await waitValue(page, 'qcalc.result.raw', 32767);
  });

  await check('unit choices (mH/µH, Ts ↔ f_s), presets', async () => {
    await page.$eval('aside.inputs', (e) => e.scrollTo(0, 0));
    await page.selectOption('select[data-unit-for="motor.ld_h"]', 'mH');
    assert((await page.inputValue('input[name="motor.ld_h"]')) === '0.6', 'Ld not shown in mH');
    await page.fill('input[name="motor.ld_h"]', '1.2');
    await waitValue(page, 'vendor.raw.LD', 120);
    await page.fill('input[name="motor.ld_h"]', '0.6');
    await waitValue(page, 'vendor.raw.LD', 60);
    await page.selectOption('select[data-unit-for="drive.ts_s"]', 'kHz');
    assert((await page.inputValue('input[name="drive.ts_s"]')) === '10', 'f_s not 10 kHz');
    await page.fill('input[name="drive.ts_s"]', '16');
    await waitValue(page, 'pu.Ts', 0.0000625 * (await valueOf(page, 'base.w_b')), 1e-12);
    await page.fill('input[name="drive.ts_s"]', '10');
    await page.selectOption('select[data-unit-for="drive.ts_s"]', 'µs');
    await page.selectOption('select[data-unit-for="motor.ld_h"]', 'µH');
    await page.selectOption('select[name="preset"]', 'ind380');
    await waitValue(page, 'vendor.raw.Voltage', 380);
    await page.selectOption('select[name="preset"]', 'seed');
    await waitValue(page, 'vendor.Rpm.value', 15022);
  });

  await check('exports: report JSON, C header, CSV of the current step', async () => {
    const grab = async (what) => {
      await page.$eval('details.export', (d) => { d.open = true; });
      const [dl] = await Promise.all([page.waitForEvent('download', { timeout: 15_000 }), page.click(`button[data-export="${what}"]`)]);
      const path = await dl.path();
      return { name: dl.suggestedFilename(), text: readFileSync(path, 'utf8') };
    };
    const j = await grab('json');
    assert(j.name.endsWith('.json') && JSON.parse(j.text).vendor.Rpm.value === 15022, 'report JSON');
    const hdr = await grab('header');
    assert(/#define PULAB_RPM\s+15022/.test(hdr.text), `C header: ${hdr.text.slice(0, 200)}`);
    const csv = await grab('csv_current');
    assert(/^t_s,/.test(csv.text) && csv.text.split('\n').length > 10, 'CSV');
  });

  await check('build served at the site root works too', async () => {
    const p2 = await newPage();
    await p2.goto(rootSrv.url);
    await ready(p2);
    await compareShown(p2, seed.expected);
    await p2.context().close();
  });

  await page.context().close();
}
