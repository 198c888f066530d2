// Loop design: the page's loop panel equals python-control (tests/golden/loop), the
// default design's phase margin with the realistic delay, a design meeting a chosen margin, the
// naive PLL's negative margin, the speed loop's integers and responses, Bode plots drawn, the
// chapter in both languages, screenshots at three widths in zh and en.
import { join } from 'node:path';

const REL = 1e-6;

export default async function loop(ctx) {
  const { check, assert, newPage, ready, valueOf, waitValue, subSrv, SHOTS, golden, leaves } = ctx;
  // The page's default input (seed motor, realistic delay, PM 60° design, J = 1e-5 kg·m²) is
  // the input of tests/golden/loop/01_seed_motor.json, whose numbers come from python-control.
  const gold = golden('loop/01_seed_motor.json').expected.loop;
  const page = await newPage();
  // The loop section arrives with the simulation (second worker): generous on a shared machine.
  const waitLoop = () => page.waitForSelector('[data-key="loop.current.d.phase_margin_deg"][data-value]', { state: 'attached', timeout: 240_000 });

  await check('loop panel: margins equal python-control (1e-6) for the seed motor', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-loop', (e) => e.scrollIntoView());
    await waitLoop();
    const shown = await page.$$eval('#panel-loop [data-key^="loop."][data-value]', (els) => els.map((e) => [e.dataset.key, e.dataset.value]));
    const want = new Map(leaves({ loop: gold }).filter(([, v]) => typeof v === 'number' || v === null));
    let n = 0;
    const bad = [];
    for (const [k, v] of shown) {
      if (!want.has(k)) continue;
      n++;
      const e = want.get(k);
      const a = JSON.parse(v);
      const ok = e === null ? a === null : Math.abs(a - e) <= REL * Math.abs(e) + 1e-9;
      if (!ok) bad.push(`${k}: page ${a}, python-control ${e}`);
    }
    assert(bad.length === 0, bad.slice(0, 10).join('\n'));
    assert(n >= 60, `only ${n} loop numbers compared`);
    console.log(`      ${n} loop numbers equal python-control`);
  });

  await check('seed motor: realistic-delay phase margin, a design meeting 60°, naive PLL negative', async () => {
    const pm = await valueOf(page, 'loop.current.d.phase_margin_deg');
    assert(pm > 50 && pm < 60, `PM ${pm}`);
    assert(Math.abs((await valueOf(page, 'loop.current.design.d.phase_margin_deg')) - 60) < 1e-9, 'design PM');
    assert((await valueOf(page, 'loop.pll.naive.gain_margin_db')) < 0, 'naive GM');
    assert((await valueOf(page, 'loop.pll.naive.stable')) === false, 'naive unstable');
    assert((await valueOf(page, 'loop.pll.naive.phase_margin_deg')) === null, 'naive PM shown as none');
    assert(Number.isInteger(await valueOf(page, 'loop.speed.pm_kp')), 'speed pm_kp');
    assert(typeof (await valueOf(page, 'loop.speed.kp_pu')) === 'number', 'speed kp_pu');
    assert(typeof (await valueOf(page, 'loop.speed.response.metrics.fixed.overshoot_pct')) === 'number', 'fixed response');
    for (const f of ['bode-current', 'bode-pll', 'speed-step', 'bode-speed']) {
      await page.$eval(`#panel-loop [data-figure="${f}"]`, (e) => e.scrollIntoView());
      await page.waitForSelector(`#panel-loop [data-figure="${f}"] .main-svg`, { state: 'attached', timeout: 60_000 });
    }
  });

  await check('robustness view: nominal and 155 °C peak-current corner equal python-control (1e-6), band and figures drawn, zh and en', async () => {
    // tests/golden/robust/01_seed_motor.json: the seed motor, analysis.robust = {} (the page
    // asks for the same defaults plus 200 tolerance samples, which leave the corners unchanged).
    const cases = golden('robust/01_seed_motor.json').expected.cases;
    const bad = [];
    let n = 0;
    for (const k of [0, 7]) {
      for (const a of ['d', 'q']) {
        for (const key of ['phase_margin_deg', 'gain_margin_db']) {
          const e = cases[k][a][key];
          const got = await valueOf(page, `loop.robust.cases.${k}.${a}.${key}`);
          n++;
          if (!(Math.abs(got - e) <= REL * Math.abs(e) + 1e-9)) bad.push(`cases.${k}.${a}.${key}: page ${got}, python-control ${e}`);
        }
      }
      const r = await valueOf(page, `loop.robust.cases.${k}.rs_ohm`);
      if (!(Math.abs(r - cases[k].rs_ohm) <= REL * cases[k].rs_ohm)) bad.push(`cases.${k}.rs_ohm ${r}`);
    }
    assert(bad.length === 0, bad.join('\n'));
    const lo = await valueOf(page, 'loop.robust.safe_bandwidth_hz.0');
    const hi = await valueOf(page, 'loop.robust.safe_bandwidth_hz.1');
    const bw = await valueOf(page, 'loop.robust.designed_bandwidth_hz.q');
    assert(lo > 0 && lo < hi && hi < 5000, `band ${lo}–${hi}`);
    // The seed's 500 Hz gains close the loop at ≈1268 Hz, above the band: its worst gain margin
    // (cold, peak current) is below 6 dB, so the page says the margins are lost.
    assert(bw > hi && (await valueOf(page, 'loop.robust.safe')) === false, `seed: bw ${bw}, band top ${hi}, safe flag`);
    assert(Math.abs((await valueOf(page, 'loop.robust.step.metrics.fixed.overshoot_pct')) - (await valueOf(page, 'loop.robust.step.metrics.float.overshoot_pct'))) < 1, 'fixed vs float overshoot at the worst case');
    for (const f of ['robust-band', 'robust-map', 'robust-step', 'robust-hist']) {
      await page.$eval(`#panel-loop [data-figure="${f}"]`, (e) => e.scrollIntoView({ block: 'center' }));
      await page.waitForSelector(`#panel-loop [data-figure="${f}"] .main-svg`, { state: 'attached', timeout: 60_000 });
    }
    for (const lang of ['zh', 'en']) {
      await page.click(`button[data-lang="${lang}"]`);
      const title = await page.$eval('#panel-loop h3.robust-title', (e) => e.textContent);
      assert(lang === 'zh' ? /鲁棒/.test(title) : /Robustness/.test(title), `${lang} title ${title}`);
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.$eval('#panel-loop h3.robust-title', (e) => e.scrollIntoView());
        await page.waitForTimeout(500);
        await page.screenshot({ path: join(SHOTS, `loop-robust-${lang}-${w}.png`) });
      }
    }
    await page.setViewportSize({ width: 1366, height: 768 });
    console.log(`      ${n} robustness margins equal python-control; safe band ${lo.toFixed(1)}–${hi.toFixed(1)} Hz, your gains ${bw.toFixed(1)} Hz`);
  });

  await check('inputs: delay none raises the margin; a 45° target is met', async () => {
    const before = await valueOf(page, 'loop.current.d.phase_margin_deg');
    await page.$eval('details[data-section="analysis"]', (d) => { d.open = true; });
    await page.selectOption('select[name="analysis.delay"]', 'none');
    await page.waitForFunction((b) => {
      const e = document.querySelector('[data-key="loop.current.d.phase_margin_deg"][data-value]');
      return e && JSON.parse(e.dataset.value) > b + 20;
    }, before, { timeout: 180_000 });
    await page.selectOption('select[name="analysis.delay"]', 'computation_pwm');
    await page.fill('input[name="analysis.target_phase_margin_deg"]', '45');
    await waitValue(page, 'loop.current.design.d.phase_margin_deg', 45, 1e-9, 180_000);
    await page.fill('input[name="analysis.target_phase_margin_deg"]', '101');
    await page.waitForSelector('[data-err-for="analysis.target_phase_margin_deg"]:not(:empty)', { state: 'attached', timeout: 180_000 });
    await page.fill('input[name="analysis.target_phase_margin_deg"]', '60');
    await waitValue(page, 'loop.current.design.d.phase_margin_deg', 60, 1e-9, 180_000);
  });

  await check('screenshots of the loop panel at 390/900/1366 px, en and zh', async () => {
    for (const lang of ['en', 'zh']) {
      await page.click(`button[data-lang="${lang}"]`);
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.$eval('#panel-loop', (e) => e.scrollIntoView());
        await page.waitForTimeout(400);
        await page.screenshot({ path: join(SHOTS, `loop-${lang}-${w}.png`) });
      }
    }
    await page.click('button[data-lang="en"]');
    await page.setViewportSize({ width: 1366, height: 900 });
    for (const f of ['bode-current', 'bode-pll', 'speed-step', 'bode-speed']) {
      await page.$eval(`#panel-loop [data-figure="${f}"]`, (e) => e.scrollIntoView({ block: 'center' }));
      await page.waitForTimeout(600);
      await page.screenshot({ path: join(SHOTS, `loop-${f}.png`) });
    }
    await page.setViewportSize({ width: 1366, height: 768 });
  });

  await check('chapter 08 renders in both languages with the loop panel embedded', async () => {
    for (const lang of ['zh', 'en']) {
      await page.click(`button[data-lang="${lang}"]`);
      await page.$eval('#panel-loop', (e) => e.scrollIntoView()); // back on its tab (Loops) from the explainer's
      await page.click('#panel-loop a.why');
      await page.waitForSelector('article.doc[data-chapter="08-loop-design"] [data-key="current_pi.d.pm_kp"][data-value]', { state: 'attached', timeout: 60_000 });
      await page.waitForSelector('article.doc [data-key="loop.current.d.phase_margin_deg"][data-value]', { state: 'attached', timeout: 60_000 });
      const errors = await page.$$eval('article.doc .katex-error', (e) => e.length);
      assert(errors === 0, `${lang}: ${errors} KaTeX errors`);
      await page.waitForTimeout(300);
      await page.screenshot({ path: join(SHOTS, `loop-doc-${lang}.png`) });
    }
    await page.click('button[data-lang="en"]');
  });
  await page.context().close();
}
