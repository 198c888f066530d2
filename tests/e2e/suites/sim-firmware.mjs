// The current-step plot shows the fixed-point trace of the firmware the reader ships
// (conventions.firmware), labelled with its name, its metrics and its wraps and saturations
// equal to CPython's; a firmware that cannot represent the motor says so at the plot.
// Screenshots of the Loops tab at 390/900/1366 px in en and zh.
// Run alone: node tests/e2e/run.mjs sim-firmware   (E2E_NO_BUILD=1 to reuse dist/)
import { join } from 'node:path';

const WIDTHS = [[390, 844], [900, 900], [1366, 768]];
const NAMES = { en: { st: 'ST fixed point', ti: 'TI' }, zh: { st: 'ST 定点', ti: 'TI' } };

export default async function simFirmware(ctx) {
  const { check, assert, newPage, subSrv, ready, cpython, golden, SHOTS } = ctx;
  const seed = golden('01_seed_motor.json');
  const link = (inp, lang) => `${subSrv.url}?lang=${lang}#in=${encodeURIComponent(JSON.stringify(inp))}`;
  const st = { ...seed.input, conventions: { ...(seed.input.conventions ?? {}), firmware: 'st' }, sim: {} };
  const want = cpython(st).sim.current.by_profile.st;

  for (const lang of ['en', 'zh']) {
    for (const [w, hgt] of WIDTHS) {
      await check(`sim-firmware: ${w} px (${lang}): the current step shows ST's fixed point, its metrics and events equal CPython`, async () => {
        const p = await newPage({ context: { viewport: { width: w, height: hgt } } });
        await p.goto(link(st, lang));
        await ready(p);
        await p.click('nav.tabs a[data-view="loops"]');
        const base = 'sim.current.by_profile.st';
        await p.waitForSelector(`#panel-current [data-key="${base}.metrics.rise_time_s"][data-value]`, { timeout: 60_000 });
        const shown = await p.$$eval(`#panel-current [data-key^="${base}."][data-value]`, (els) => els.map((e) => [e.dataset.key, JSON.parse(e.dataset.value)]));
        const expect = (k) => k.split('.').slice(4).reduce((o, x) => o[x], want);
        const bad = shown.filter(([k, v]) => (typeof v === 'number' && !Number.isInteger(v) ? Math.abs(v - expect(k)) > 1e-12 * Math.abs(expect(k)) : v !== expect(k)));
        assert(shown.length >= 11 && bad.length === 0, `${shown.length} numbers, differing ${JSON.stringify(bad)}`);
        // the plot's legend names the shipped firmware; the Inovance column is not shown
        await p.$eval('#panel-current .figure', (e) => e.scrollIntoView({ block: 'center' }));
        await p.waitForSelector('#panel-current .plot-host .main-svg', { timeout: 30_000 });
        const legend = await p.$$eval('#panel-current .legendtext', (ts) => ts.map((x) => x.textContent));
        assert(legend.some((x) => x.startsWith(NAMES[lang].st)), `legend ${legend}`);
        assert((await p.$('#panel-current [data-key="sim.current.metrics.fixed.rise_time_s"]')) === null, 'Inovance column shown for ST');
        await p.waitForTimeout(300);
        await p.screenshot({ path: join(SHOTS, `sim-firmware-${w}-${lang}-st.png`) });
        await p.context().close();
      });
    }
  }

  await check('sim-firmware: Inovance by default; picking NXP in "Firmware you ship" redraws with NXP\'s run (equal CPython)', async () => {
    const inp = { ...seed.input, sim: {} };
    const want = cpython(inp).sim.current;
    const p = await newPage({ context: { viewport: { width: 1366, height: 768 } } });
    await p.goto(link(inp, 'en'));
    await ready(p);
    await p.click('nav.tabs a[data-view="loops"]');
    const ino = '#panel-current [data-key="sim.current.metrics.fixed.rise_time_s"][data-value]';
    await p.waitForSelector(ino, { timeout: 60_000 });
    assert(await p.$eval(ino, (e) => JSON.parse(e.dataset.value)) === want.metrics.fixed.rise_time_s, 'Inovance rise time');
    await p.$eval('#panel-current .figure', (e) => e.scrollIntoView({ block: 'center' }));
    await p.waitForSelector('#panel-current .plot-host .main-svg', { timeout: 30_000 });
    const legend = () => p.$$eval('#panel-current .legendtext', (ts) => ts.map((x) => x.textContent));
    assert((await legend()).some((x) => x.startsWith('Inovance fixed point')), `legend ${await legend()}`);
    await p.selectOption('select[name="conventions.firmware"]', 'nxp');
    const nxp = '#panel-current [data-key="sim.current.by_profile.nxp.metrics.rise_time_s"][data-value]';
    await p.waitForSelector(nxp, { timeout: 60_000 });
    const nxpWant = cpython({ ...inp, conventions: { ...(inp.conventions ?? {}), firmware: 'nxp' } }).sim.current.by_profile.nxp;
    assert(await p.$eval(nxp, (e) => JSON.parse(e.dataset.value)) === nxpWant.metrics.rise_time_s, 'NXP rise time');
    await p.waitForFunction(() => [...document.querySelectorAll('#panel-current .legendtext')].some((x) => x.textContent.startsWith('NXP fixed point')), null, { timeout: 30_000 });
    await p.context().close();
  });

  await check('sim-firmware: Microchip at 20 kHz wraps: the count (equal CPython) is marked an error and the review lists it', async () => {
    const inp = { ...seed.input, current_loop: { bandwidth_hz: 20000 }, conventions: { ...(seed.input.conventions ?? {}), firmware: 'microchip' }, sim: {} };
    const want = cpython(inp);
    const wraps = want.sim.current.by_profile.microchip.events.wrap;
    assert(wraps > 0 && want.review.findings.some((f) => f.code === 'pi_wrap'), 'CPython: no wraps here');
    const p = await newPage({ context: { viewport: { width: 1366, height: 768 } } });
    await p.goto(link(inp, 'en'));
    await ready(p);
    await p.click('nav.tabs a[data-view="loops"]');
    const sel = '#panel-current [data-key="sim.current.by_profile.microchip.events.wrap"][data-value]';
    await p.waitForSelector(sel, { timeout: 60_000 });
    assert(await p.$eval(sel, (e) => JSON.parse(e.dataset.value)) === wraps, 'wrap count');
    await p.waitForFunction((s) => document.querySelector(s)?.dataset.findingSev === 'error', sel, { timeout: 30_000 });
    await p.waitForSelector('.panel-review li.finding[data-finding="sim.current.by_profile.microchip.events.wrap"]', { state: 'attached', timeout: 30_000 });
    await p.$eval(sel, (e) => e.scrollIntoView({ block: 'center' }));
    await p.waitForTimeout(300);
    await p.screenshot({ path: join(SHOTS, 'sim-firmware-1366-en-microchip-wraps.png') });
    await p.context().close();
  });

  await check('sim-firmware: a firmware that cannot represent the motor says so at the plot (TI, Kp beyond IQ24)', async () => {
    // 500 kHz bandwidth: TI's Kp = 333 per unit does not fit IQ24's ±128; NXP, ST, Microchip run.
    const inp = { ...seed.input, current_loop: { bandwidth_hz: 500000 }, conventions: { ...(seed.input.conventions ?? {}), firmware: 'ti' }, sim: {} };
    const fields = cpython(inp).sim.current.by_profile.ti.problems.map((x) => x.field);
    assert(fields.length > 0, 'CPython runs TI here');
    for (const lang of ['en', 'zh']) {
      const p = await newPage({ context: { viewport: { width: 900, height: 900 } } });
      await p.goto(link(inp, lang));
      await ready(p);
      await p.click('nav.tabs a[data-view="loops"]');
      const sel = '#panel-current .sim-no-trace[data-firmware="ti"]';
      await p.waitForSelector(sel, { state: 'visible', timeout: 60_000 });
      const text = await p.$eval(sel, (e) => e.textContent);
      assert(fields.every((f) => text.includes(f)), `message ${text} misses ${fields}`);
      // the message sits right above the plot
      const [msg, fig] = await p.$$eval(`${sel}, #panel-current .figure`, (els) => els.map((e) => e.getBoundingClientRect().bottom));
      assert(msg <= fig, 'message not above the plot');
      await p.$eval(sel, (e) => { e.scrollIntoView(); window.scrollBy(0, -120); });
      await p.waitForTimeout(300);
      await p.screenshot({ path: join(SHOTS, `sim-firmware-900-${lang}-ti-cannot.png`) });
      await p.context().close();
    }
  });
}
