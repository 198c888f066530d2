// Above base speed: the view's numbers equal CPython pulab for the page's motor and the form's
// options, a bad option is shown, and the view is looked at in zh and en at 390/900/1366 px.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function fw({ check, assert, newPage, subSrv, ready, waitValue, cpython, compareShown, SHOTS, GOLDEN }) {
  // MathWorks' BLY171D on a 24 V DRV8312 kit: base speed 5393 rpm (mcb.PMSMSpeeds)
  const bly = { motor: { rated_voltage_v: 24, rated_current_a: 1.8 / Math.SQRT2, rated_freq_hz: 4000 * 4 / 60,
    rs_ohm: 0.75, ld_h: 1.05e-3, lq_h: 1.05e-3, bemf_v: 3.8 * 4 / Math.SQRT2, pole_pairs: 4 }, drive: { udc_v: 24, ts_s: 5e-5 } };
  const page = await newPage();
  const open = async () => {
    await page.click('nav.tabs a[data-view="loops"]');
    await page.$eval('#panel-fw', (e) => e.scrollIntoView());
  };

  await check('fw: a panel opened before the simulations answer stays in view when the loop panel above it grows', async () => {
    const p = await newPage();
    await p.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(bly))}`);
    await ready(p);
    await p.click('nav.tabs a[data-view="loops"]');
    await p.$eval('#panel-fw', (e) => e.scrollIntoView());
    const top0 = await p.$eval('#panel-fw', (e) => e.getBoundingClientRect().top);
    const loop0 = await p.$eval('#panel-loop', (e) => e.getBoundingClientRect().height);
    // the loop panel's analysis comes with the simulations
    await p.waitForFunction((h0) => document.querySelector('#panel-loop').getBoundingClientRect().height > h0 + 1000, loop0, { timeout: 60_000 });
    await p.waitForTimeout(300);
    const top1 = await p.$eval('#panel-fw', (e) => e.getBoundingClientRect().top);
    assert(Math.abs(top1 - top0) <= 2, `the panel moved from ${top0} to ${top1} px`);
    await p.context().close();
  });

  await check('fw: base and maximum speed equal CPython pulab; 5393 rpm for the BLY171D', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(bly))}`);
    await ready(page);
    await open();
    await page.waitForSelector('#panel-fw [data-key="fw.base_speed_rpm"][data-value]', { timeout: 60_000 });
    const want = cpython({ ...bly, analysis: { fw: {} } });
    const n = await compareShown(page, want, '#panel-fw');
    assert(n >= 6, `only ${n} numbers compared`);
    assert(Math.round(want.fw.base_speed_rpm) === 5393, 'MathWorks base speed');
    await page.waitForSelector('#panel-fw [data-keep="fw-plane"] .main-svg', { timeout: 60_000 });
  });

  await check('fw: a current limit typed in the form recomputes; a bad one is named', async () => {
    const box = 'input[name="analysis.fw.current_limit_a"]';
    await page.$eval(box, (e) => e.closest('details')?.setAttribute('open', ''));
    await page.fill(box, '6');
    // typing scrolled the form's box into view; the view asks pulab only while it is on screen
    await page.$eval('#panel-fw', (e) => e.scrollIntoView());
    const want = cpython({ ...bly, analysis: { fw: { current_limit_a: 6 } } });
    assert(want.fw.max_speed_rpm === null, 'ψ/L_d = 4.99 A inside a 6 A limit: unbounded');
    await waitValue(page, 'fw.base_speed_rpm', want.fw.base_speed_rpm, 1e-12, 60_000);
    await page.waitForFunction(() => document.querySelector('[data-key="fw.max_speed_rpm"]')?.getAttribute('data-value') === 'null');
    await page.fill(box, '-3');
    await page.$eval('#panel-fw', (e) => e.scrollIntoView());
    await page.waitForFunction(() => (document.querySelector('[data-err-for="analysis.fw.current_limit_a"]')?.textContent ?? '').length > 0, null, { timeout: 30_000 });
    await page.fill(box, '');
    await page.$eval('#panel-fw', (e) => e.scrollIntoView());
    await page.waitForFunction(() => (document.querySelector('[data-err-for="analysis.fw.current_limit_a"]')?.textContent ?? '') === '', null, { timeout: 30_000 });
  });

  await check('fw: an interior motor\'s vendor tables (generic, Microchip AN1078 and feed-forward, TI, ST, NXP) equal CPython pulab', async () => {
    // motulator's 2.2-kW interior motor (tests/golden/fw_tables/03_motulator_2k2_ipm.json)
    const gold = JSON.parse(readFileSync(join(GOLDEN, 'fw_tables', '03_motulator_2k2_ipm.json'), 'utf8'));
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(gold.input))}`);
    await ready(page);
    await open();
    // TI's MTPA exists for an interior motor only: the BLY171D's view is gone when it shows
    await page.waitForSelector('#panel-fw [data-key="fw.tables.ti_mtpa.kconst"][data-value]', { timeout: 60_000 });
    const want = cpython(gold.input);
    const n = await compareShown(page, want, '#panel-fw');
    const keys = await page.$$eval('#panel-fw [data-key^="fw.tables."]', (els) => els.map((e) => e.getAttribute('data-key')));
    for (const k of ['generic.error_bound', 'generic.x_step_digits', 'generic_fw.error_bound', 'microchip_fw.fwonspeed', 'ti_mtpa.kconst',
      'ti_mtpa.error_sampled', 'st_fw.constants.wVoltLimit_Ref.value', 'st_fw.steady.max_speed_rpm', 'nxp_fw.constants.M1_CLOOP_LIMIT.value', 'ti_fwc.steady.max_speed_rpm', 'microchip_ff.constants.Ls.value']) {
      assert(keys.includes(`fw.tables.${k}`), `fw.tables.${k} not shown`);
    }
    assert(n >= 40, `only ${n} numbers compared`);
    const c = await page.$$eval('#panel-fw pre.c-array', (els) => els.map((e) => e.textContent ?? ''));
    assert(c.some((t) => t.includes('#define SPEED_INDEX_CONST')) && c.some((t) => t.includes('static const int16_t mtpa_id_of_iq[8]')), 'C exports');
  });

  await check('fw: screenshots at 390/900/1366 px, zh and en', async () => {
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await open();
        await page.waitForSelector('#panel-fw [data-keep="fw-speed"] .main-svg', { timeout: 60_000 });
        const overflow = await page.$eval('#panel-fw', (e) => e.scrollWidth - e.clientWidth);
        assert(overflow <= 1, `fw panel overflows by ${overflow}px at ${w} (${lang})`);
        await (await page.$('#panel-fw')).screenshot({ path: join(SHOTS, `fw-${w}-${lang}.png`) });
      }
    }
  });
  await page.close();
}
