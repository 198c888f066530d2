// Sensorless: the view's numbers (design, budget, NXP's, ST's, Microchip's and TI's constants) equal CPython pulab for
// the page's motor with the observer defaults and with a typed option, a bad option is named at
// its field, both plots are drawn, and the view is looked at in zh and en at 390/900/1366 px.
import { join } from 'node:path';

export default async function observer({ check, assert, newPage, subSrv, ready, waitValue, cpython, compareShown, SHOTS }) {
  // the seed's motor (docs: the lowest speed worked by hand, 569.12 rpm with the defaults)
  const seed = { motor: { rated_voltage_v: 17, rated_current_a: 1.5, rated_freq_hz: 220, rs_ohm: 1.5,
    ld_h: 0.0006, lq_h: 0.0006, bemf_v: 12, pole_pairs: 4 }, drive: { udc_v: 24, ts_s: 0.0001 } };
  const asked = (o) => ({ ...seed, observer: o, profiles: { nxp: {}, st: {}, microchip: {}, ti: {} } });
  const page = await newPage();
  /** A plot is drawn once it is on screen (figures/figure.ts, whenVisible), and a re-render after
   * a language or width change may move the page under it: scroll it into view until drawn. */
  const seeFigure = async (fig) => {
    const sel = `#panel-observer [data-keep="${fig}"]`;
    for (let k = 0; k < 20; k++) {
      await page.$eval(sel, (e) => e.scrollIntoView({ block: 'center' }));
      if (await page.waitForSelector(`${sel} .main-svg`, { timeout: 3_000 }).then(() => true, () => false)) return;
    }
    throw new Error(`${fig} was not drawn`);
  };
  const open = async () => {
    await page.click('nav.tabs a[data-view="loops"]');
    await page.$eval('#panel-observer', (e) => e.scrollIntoView());
  };

  await check('observer: defaults — every number equals CPython pulab; 569 rpm lowest speed', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(seed))}`);
    await ready(page);
    await open();
    await page.waitForSelector('#panel-observer [data-key="observer.budget.min_speed_rpm"][data-value]', { timeout: 60_000 });
    const want = cpython(asked({}));
    const n = await compareShown(page, want, '#panel-observer');
    assert(n >= 40, `only ${n} numbers compared`);
    assert(Math.abs(want.observer.budget.min_speed_rpm - 569.12) < 0.01, 'hand-worked lowest speed');
    for (const fig of ['obs-poles', 'obs-budget']) await seeFigure(fig);
  });

  await check('observer: Microchip\'s and TI\'s tables list their estimator constants, TI\'s as float32 reals', async () => {
    const want = cpython(asked({}));
    for (const [v, k] of [['microchip', 'KFILTER_ESDQ'], ['microchip', 'MCAF_PLL_DT_ANGULAR'], ['ti', 'Fdsmopos'], ['ti', 'Kslf']]) {
      const key = `profiles.${v}.constants.${k}.value`;
      const shown = await page.$eval(`#panel-observer [data-key="${key}"]`, (e) => e.getAttribute('data-value'));
      assert(JSON.parse(shown) === want.profiles[v].constants[k].value, `${key}: ${shown}`);
    }
    const tiInt = await page.$eval('#panel-observer [data-key="profiles.ti.constants.Fdsmopos.value"]', (e) => e.classList.contains('int'));
    assert(!tiInt, 'TI\'s float32 shown as an integer');
  });

  await check('observer: a typed bandwidth recomputes; a bad one is named at its field', async () => {
    const box = 'input[name="observer.bemf_f0_hz"]';
    await page.$eval(box, (e) => e.closest('details')?.setAttribute('open', ''));
    await page.fill(box, '600');
    await page.$eval('#panel-observer', (e) => e.scrollIntoView());
    const want = cpython(asked({ bemf_f0_hz: 600 }));
    await waitValue(page, 'observer.design.bemf.kp_v_per_a', want.observer.design.bemf.kp_v_per_a, 1e-12, 60_000);
    await waitValue(page, 'profiles.nxp.constants.M1_BEMF_DQ_KP_GAIN.value',
      want.profiles.nxp.constants.M1_BEMF_DQ_KP_GAIN.value, 0, 60_000);
    await page.fill(box, '-3');
    await page.$eval('#panel-observer', (e) => e.scrollIntoView());
    await page.waitForFunction(() => (document.querySelector('[data-err-for="observer.bemf_f0_hz"]')?.textContent ?? '').length > 0, null, { timeout: 30_000 });
    await page.fill(box, '');
    await page.$eval('#panel-observer', (e) => e.scrollIntoView());
    await page.waitForFunction(() => (document.querySelector('[data-err-for="observer.bemf_f0_hz"]')?.textContent ?? '') === '', null, { timeout: 30_000 });
  });

  await check('observer: a pasted MCAT header gives MCAT\'s motor and integers; ST by the Workbench rule', async () => {
    const { readFileSync } = await import('node:fs');
    const text = readFileSync(join(process.cwd(), 'tests/data/headers/nxp/m1_pmsm_appconfig.h'), 'utf8');
    const mcat = JSON.parse(text.match(/\/\*\s*(\{[\s\S]*?"parameters"[\s\S]*?\})\s*\*\//)[1]);
    await page.$eval('#panel-observer', (e) => e.scrollIntoView());
    await page.fill('textarea[name="profiles.nxp.mcat"]', text);
    const want = cpython({ observer: {}, profiles: { nxp: { mcat }, st: {} } });
    assert(want.profiles.nxp.constants.M1_BEMF_DQ_KP_GAIN.value === 12589, 'MCAT printed ACC32(0.384202)');
    await waitValue(page, 'profiles.nxp.constants.M1_BEMF_DQ_KP_GAIN.value', 12589, 0, 60_000);
    await waitValue(page, 'profiles.st.constants.GAIN1.value', want.profiles.st.constants.GAIN1.value, 0, 60_000);
    assert(await page.$eval('#panel-observer [data-st-rule]', (e) => e.getAttribute('data-st-rule')) === 'workbench', 'ST rule note');
    // pulab finds MCAT's JSON in the pasted text, or refuses it at the box (once, not also as an alert)
    await page.fill('textarea[name="profiles.nxp.mcat"]', '{not json');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="profiles.nxp.mcat"]')?.textContent ?? '').includes('MCAT'), null, { timeout: 30_000 });
    assert(await page.$('#panel-observer .sim-error') === null, 'the MCAT refusal is shown twice');
    await page.fill('textarea[name="profiles.nxp.mcat"]', '');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="profiles.nxp.mcat"]')?.textContent ?? '') === '', null, { timeout: 30_000 });
  });

  await check('observer: screenshots at 390/900/1366 px, zh and en', async () => {
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await open();
        await seeFigure('obs-budget');
        await page.$eval('#panel-observer', (e) => e.scrollIntoView());
        const overflow = await page.$eval('#panel-observer', (e) => e.scrollWidth - e.clientWidth);
        assert(overflow <= 1, `observer panel overflows by ${overflow}px at ${w} (${lang})`);
        await (await page.$('#panel-observer')).screenshot({ path: join(SHOTS, `observer-${w}-${lang}.png`) });
      }
    }
  });
  await page.close();
}
