// "Start from a datasheet", then the EMRAX 228 LV values typed field by field (the golden input):
// the current-step simulation is run again for the new motor (the Loops plots stopped showing the
// example motor's), and the derived DC bus shows as "= 160" under Drive → Udc.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function datasheetFlow({ check, assert, newPage, subSrv, ready, ROOT }) {
  const golden = JSON.parse(readFileSync(join(ROOT, 'tests/golden/datasheets/emrax_228_lv.json'), 'utf8')).input;
  const page = await newPage();
  const VS_SI = '[data-key="sim.current.metrics.fixed_vs_si_max_abs_a"]';
  const vsSi = () => page.$eval(VS_SI, (e) => e.dataset.value).catch(() => null);
  await check('datasheet flow: the step simulation is of the typed motor; the derived DC bus is the Udc placeholder', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    await page.waitForSelector(VS_SI, { state: 'attached', timeout: 60_000 });
    const before = await vsSi();
    await page.click('button.from-datasheet');
    // in the order a reader types them: the motor, the datasheet, the drive
    for (const sec of ['motor', 'datasheet', 'drive']) {
      const vals = golden[sec];
      for (const [k, v] of Object.entries(vals)) {
        const name = `${sec}.${k}`;
        const sel = `.inputs [name="${name}"]`;
        await page.$eval(sel, (e) => e.closest('details')?.setAttribute('open', ''));
        const tag = await page.$eval(sel, (e) => e.tagName);
        if (tag === 'SELECT') await page.selectOption(sel, String(v));
        // as printed: µH and µs (the fields' default units)
        else await page.fill(sel, String(/_h$|_s$/.test(k) ? Number((v * 1e6).toPrecision(12)) : v));
      }
    }
    await page.waitForFunction(() => document.documentElement.dataset.numbers === 'live');
    const ph = await page.$eval('.inputs input[name="drive.udc_v"]', (e) => e.placeholder);
    assert(ph === '= 160', `drive.udc_v placeholder ${JSON.stringify(ph)}`);
    await page.$eval('#panel-current', (e) => e.scrollIntoView());
    // The example motor's run stays on screen if the new one is never simulated.
    await page.waitForFunction(([sel, b]) => document.querySelector(sel)?.dataset.value !== b, [VS_SI, before], { timeout: 60_000 })
      .catch(() => undefined);
    const after = await vsSi();
    assert(after !== null && after !== before, `fixed − SI ${after} A, still the example motor's ${before} A`);
  });
  await page.context().close();
}
