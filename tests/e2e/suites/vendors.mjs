// Vendor profiles panel: profiles equal CPython pulab, hardware inputs recompute,
// bad input is shown at its field, the translator round-trips, each vendor header downloads.
import { join } from 'node:path';

export default async function vendors({ check, assert, newPage, subSrv, ready, waitValue, valueOf, cpython, golden, compareShown, SHOTS }) {
  const seed = golden('01_seed_motor.json');
  const page = await newPage();
  const key = (k) => `#panel-vendors [data-key="${k}"][data-value]`;

  await check('vendors: every profile constant shown equals CPython pulab', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-vendors', (e) => e.scrollIntoView());
    await page.waitForSelector(key('profiles.microchip.constants.KIP.value'), { timeout: 30_000 });
    const want = cpython({ ...seed.input, profiles: {} });
    const n = await compareShown(page, want, '#panel-vendors');
    assert(n >= 150, `only ${n} profile numbers compared`);
    assert((await valueOf(page, 'profiles.ti.constants.Kp_Iq.value')) === want.profiles.ti.constants.Kp_Iq.value, 'TI Kp_Iq');
    console.log(`      ${n} numbers equal CPython`);
  });

  await check('vendors: a hardware input recomputes; a bad one is shown at its field', async () => {
    const want = cpython({ ...seed.input, profiles: { ti: { full_scale_current_a: 10 } } });
    await page.fill('input[name="profiles.ti.full_scale_current_a"]', '10');
    await waitValue(page, 'profiles.ti.constants.Kp_Iq.value', want.profiles.ti.constants.Kp_Iq.value);
    await page.fill('input[name="profiles.ti.full_scale_current_a"]', '-2');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="profiles.ti.full_scale_current_a"]')?.textContent ?? '').length > 0);
    await page.fill('input[name="profiles.ti.full_scale_current_a"]', '');
    await waitValue(page, 'profiles.ti.constants.Kp_Iq.value', cpython({ ...seed.input, profiles: {} }).profiles.ti.constants.Kp_Iq.value);
  });

  await check('vendors: translator round-trips Inovance → … → Inovance; bad integers at the field', async () => {
    await page.waitForSelector(key('translation.round_trip.delta.pm_kp'), { timeout: 60_000 });
    assert(Math.abs(await valueOf(page, 'translation.round_trip.delta.pm_kp')) <= 1, 'pm_kp round trip');
    assert(Math.abs(await valueOf(page, 'translation.round_trip.delta.pm_ki')) <= 1, 'pm_ki round trip');
    await page.selectOption('select[name="translate.from"]', 'ti');
    await page.waitForSelector('input[name="translate.values.Kp_Iq"]');
    await page.fill('input[name="translate.values.Kp_Iq"]', '0');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="translate.values.Kp_Iq"]')?.textContent ?? '').length > 0);
    await page.fill('input[name="translate.values.Kp_Iq"]', '5590440');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="translate.values.Kp_Iq"]')?.textContent ?? '') === '');
    await page.waitForSelector(key('translation.profiles.nxp.values.M1_Q_KP_GAIN'));
  });

  await check('vendors: each vendor header downloads with its own names', async () => {
    for (const [v, word] of [['ti', 'USER_IQ_FULL_SCALE_CURRENT_A'], ['nxp', 'M1_Q_KP_GAIN'], ['st', 'PID_TORQUE_KP_DEFAULT'], ['microchip', 'KIP_SCALE'], ['inovance', 'PULAB_RPM']]) {
      const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`button[data-header="${v}"]`)]);
      const path = await dl.path();
      const { readFileSync } = await import('node:fs');
      const text = readFileSync(path, 'utf8');
      assert(text.includes(`#define ${word}`), `${v} header lacks ${word}`);
    }
  });

  await check('vendors: screenshots at 390/900/1366 px, zh and en', async () => {
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await page.$eval('#panel-vendors', (e) => e.scrollIntoView());
        await page.waitForTimeout(200);
        await page.screenshot({ path: join(SHOTS, `vendors-${lang}-${w}.png`) });
        await page.$eval('#panel-vendors .vendors-translate', (e) => e.scrollIntoView());
        await page.waitForTimeout(100);
        await page.screenshot({ path: join(SHOTS, `vendors-translate-${lang}-${w}.png`) });
      }
    }
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
    assert(overflow <= 1, `page scrolls sideways by ${overflow} px`);
  });
  await check('vendors: ?embed=vendors shows the panel alone with its numbers', async () => {
    const p2 = await newPage();
    await p2.goto(`${subSrv.url}?embed=vendors`);
    await p2.waitForSelector('[data-key="profiles.nxp.constants.M1_Q_KP_GAIN.value"][data-value]', { timeout: 60_000 });
    assert((await p2.$$('section.panel')).length === 1, 'one panel');
    await p2.context().close();
  });
  await check('vendors: a motor beyond Inovance\'s Uint16 shows the physics and the other firmware; the limit sits at the Inovance panel', async () => {
    const robot = golden('23_limit_robot_28krpm.json');
    const want = cpython({ ...robot.input, profiles: {} });
    const p3 = await newPage();
    await p3.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(robot.input))}`);
    await ready(p3);
    await p3.waitForSelector('#panel-vendor .firmware-limits [data-field="raw.FullFreq01"]', { timeout: 30_000 });
    assert(await p3.evaluate(() => document.documentElement.dataset.numbers) === 'live', 'data-numbers live');
    assert(await valueOf(p3, 'base.U_b') === want.base.U_b, 'U_b shown');
    assert(await valueOf(p3, 'vendor.Rpm.value') === want.vendor.Rpm.value, 'Rpm still computed');
    const fieldErr = await p3.$eval('[data-err-for="drive.base_freq_hz"]', (e) => e.textContent ?? '').catch(() => '');
    assert(fieldErr === '', `an input error at drive.base_freq_hz: ${fieldErr}`);
    await p3.$eval('#panel-vendors', (e) => e.scrollIntoView());
    await p3.waitForSelector('#panel-vendors [data-key="profiles.ti.constants.Kp_Iq.value"][data-value]', { timeout: 60_000 });
    assert(await valueOf(p3, 'profiles.ti.constants.Kp_Iq.value') === want.profiles.ti.constants.Kp_Iq.value, 'TI Kp_Iq');
    for (const w of [390, 1366]) {
      await p3.setViewportSize({ width: w, height: 900 });
      await p3.$eval('#panel-vendor', (e) => e.scrollIntoView());
      await p3.waitForTimeout(150);
      await p3.screenshot({ path: join(SHOTS, `vendor-limits-en-${w}.png`) });
    }
    await p3.context().close();
  });
  await page.context().close();
}
