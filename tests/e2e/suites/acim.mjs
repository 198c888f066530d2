// Induction motors: a share link with motor.kind = acim shows the Induction motor panel equal to
// CPython pulab (every number a data-key), the PMSM-only panels say they do not apply, the form's
// kind switches which fields apply and recomputes, and the panel is looked at in zh and en.
import { join } from 'node:path';

export default async function acim({ check, assert, newPage, subSrv, ready, waitValue, cpython, golden, compareShown, SHOTS }) {
  const st = golden('acim/01_st_mez_acim.json').input;
  const page = await newPage();
  // an induction motor's report has no vendor.Rpm (what `ready` waits for): its own first number
  const acimReady = (p) => p.waitForSelector('#panel-acim [data-key="acim.tau_r_s"][data-value]', { timeout: 60_000 });

  await check('acim: a share link shows the induction motor as CPython pulab computes it', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(st))}`);
    await acimReady(page);
    const n = await compareShown(page, cpython(st), '#panel-acim');
    assert(n >= 70, `only ${n} induction-motor numbers compared`);
    const na = await page.$eval('#panel-pu', (e) => e.textContent ?? '');
    assert(na.includes('Does not apply to an induction motor'), `pu panel: ${na.slice(0, 80)}`);
    const chip = await page.$eval('section.answer [data-key="current_pi.d.pm_kp"]', (e) => Number(e.dataset.value));
    assert(chip === cpython(st).current_pi.d.pm_kp, `answer strip pm_kp ${chip}`);
  });

  await check('acim: the form switches by motor.kind and recomputes', async () => {
    const seed = golden('01_seed_motor.json').input;
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(seed))}`);
    await ready(page);
    assert(await page.$eval('input[name="motor.rr_ohm"]', (e) => e.disabled), 'R_r enabled for a PMSM');
    assert(await page.$eval('input[name="sim.flux.startup_s"]', (e) => e.disabled), 'the flux build-up enabled for a PMSM');
    await page.selectOption('select[name="motor.kind"]', 'acim');
    assert(await page.$eval('input[name="motor.ld_h"]', (e) => e.disabled), 'L_d enabled for an induction motor');
    for (const [k, v] of [['rated_speed_rpm', '3200'], ['rr_ohm', '1.2'], ['lm_h', '20000'], ['lls_h', '1000'], ['llr_h', '1000']]) {
      await page.$eval(`[name="motor.${k}"]`, (e) => e.closest('details')?.setAttribute('open', ''));
      await page.fill(`input[name="motor.${k}"]`, v);  // inductances in µH, the form's first unit
    }
    const inp = { motor: { kind: 'acim', rated_voltage_v: 17, rated_current_a: 1.5, rated_freq_hz: 220, rs_ohm: 1.5,
      pole_pairs: 4, rated_speed_rpm: 3200, rr_ohm: 1.2, lm_h: 0.02, lls_h: 0.001, llr_h: 0.001 }, drive: seed.drive };
    await waitValue(page, 'acim.tau_r_s', cpython(inp).acim.tau_r_s);
  });

  // the current step (i_q at 20 Hz) and the flux build-up, as CPython simulates them
  const withSim = { ...st, sim: { current: { axis: 'q', speed_hz: 20 } } };
  const simReady = (p) => p.waitForSelector('#panel-acim [data-key="sim.flux.metrics.si.flux_95_s"][data-value]', { timeout: 120_000 });

  await check('acim: the simulation draws the current step and flux build-up as CPython computes them', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(withSim))}`);
    await acimReady(page);
    await page.click('nav.tabs a[data-view="design"]');
    await page.$eval('#panel-acim [data-keep="acim-flux"]', (e) => e.scrollIntoView());
    await simReady(page);
    // every simulation the page asked for has answered (or was superseded): the numbers shown are
    // the newest input's, not an earlier request's still on screen
    await page.waitForFunction(() => {
      const d = document.documentElement.dataset;
      return Number(d.simPosted ?? 0) > 0 && Number(d.simPosted) === Number(d.simDone ?? 0) + Number(d.simSuperseded ?? 0);
    }, null, { timeout: 120_000 });
    const want = cpython(withSim);
    const n = await compareShown(page, want, '#panel-acim');
    assert(n >= 100, `only ${n} induction-motor numbers compared with the simulation`);
    for (const k of ['sim.flux.metrics.si.flux_95_s', 'sim.flux.metrics.fixed.vs_si_max_abs_a', 'sim.current.metrics.si.rise_time_s',
      'sim.current.by_profile.ti.metrics.vs_si_max_abs_a', 'sim.flux.by_profile.ti.events.wrap']) {
      assert(await page.$(`#panel-acim [data-key="${k}"]`), `${k} not shown`);
    }
    for (const f of ['acim-current', 'acim-flux']) {
      await page.waitForSelector(`#panel-acim [data-keep="${f}"] .plot-host .main-svg`, { timeout: 60_000 });
    }
  });

  await check('acim: the start-up time in the form gives the torque-before-flux finding (zh and en)', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(withSim))}`);
    await acimReady(page);
    await page.$eval('[name="sim.flux.startup_s"]', (e) => e.closest('details')?.setAttribute('open', ''));
    assert(!(await page.$eval('input[name="sim.flux.startup_s"]', (e) => e.disabled)), 'startup_s disabled for an induction motor');
    await page.fill('input[name="sim.flux.startup_s"]', '200');   // ms, the field's first unit
    await page.click('nav.tabs a[data-view="design"]');
    await page.$eval('#panel-acim [data-keep="acim-flux"]', (e) => e.scrollIntoView());
    const item = await page.waitForSelector('#panel-review li[data-finding="sim.flux.metrics.si.flux_95_s"]', { timeout: 120_000 });
    const text = await item.textContent();
    assert(text.includes('0.2 s') && text.includes('0.461'), `finding: ${text}`);
    await page.click('button[data-lang="zh"]');
    const zh = await page.$eval('#panel-review li[data-finding="sim.flux.metrics.si.flux_95_s"]', (e) => e.textContent);
    assert(zh.includes('预励磁'), `zh finding: ${zh}`);
    await page.click('button[data-lang="en"]');
  });

  await check('acim: the board view takes an induction motor (torque per count from k_T)', async () => {
    const inp = { ...st, board: { current: { shunt_ohm: 0.01, gain: 20, adc_bits: 12, adc_ref_v: 3.3 },
      pwm: { freq_hz: 10000, deadtime_s: 1e-6, clock_hz: 100e6 } } };
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(inp))}`);
    await page.click('nav.tabs a[data-view="firmware"]');
    await page.waitForSelector('#panel-board [data-key="board.current.nm_per_count"][data-value]', { timeout: 60_000 });
    const n = await compareShown(page, cpython(inp), '#panel-board');
    assert(n >= 10, `only ${n} board numbers compared`);
    assert(!(await page.$('#panel-board .acim-na')), 'the board panel says it does not apply');
  });

  await check('acim: screenshots at 390, 900 and 1366 px, zh and en, without overflow', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(withSim))}`);
    await acimReady(page);
    await page.click('nav.tabs a[data-view="design"]');
    await page.$eval('#panel-acim [data-keep="acim-flux"]', (e) => e.scrollIntoView());
    await simReady(page);
    for (const f of ['acim-current', 'acim-flux']) {
      await page.$eval(`#panel-acim [data-keep="${f}"]`, (e) => e.scrollIntoView());
      await page.waitForSelector(`#panel-acim [data-keep="${f}"] .plot-host .main-svg`, { timeout: 60_000 });
    }
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await page.$eval('#panel-acim', (e) => e.scrollIntoView());
        const overflow = await page.$eval('#panel-acim', (e) => e.scrollWidth - e.clientWidth);
        assert(overflow <= 1, `acim panel overflows by ${overflow}px at ${w} (${lang})`);
        await (await page.$('#panel-acim')).screenshot({ path: join(SHOTS, `acim-${w}-${lang}.png`) });
        for (const f of ['acim-current', 'acim-flux']) {   // plots are drawn when in view
          const fig = `#panel-acim [data-keep="${f}"]`;
          await page.$eval(fig, (e) => e.scrollIntoView({ block: 'center' }));
          await page.waitForSelector(`${fig} .plot-host .main-svg`, { timeout: 60_000 });
          const over = await page.$eval(fig, (e) => e.scrollWidth - e.clientWidth);
          assert(over <= 1, `${f} overflows by ${over}px at ${w} (${lang})`);
          await (await page.$(fig)).screenshot({ path: join(SHOTS, `${f}-${w}-${lang}.png`) });
        }
      }
    }
  });
  await page.close();
}
