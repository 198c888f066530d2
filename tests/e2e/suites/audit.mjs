// Audit view: a pasted NXP MCAT header and a chosen ST MCSDK file set are audited on the page to the
// same numbers as CPython pulab (every data-key the view shows), a header of no known vendor is
// named at the text box, and the view is looked at in en and zh at 390, 900 and 1366 px.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function audit({ check, assert, newPage, subSrv, ready, compareShown, waitValue, ROOT, SHOTS, cpython: report }) {
  const dir = join(ROOT, 'tests/data/headers');
  const nxp = readFileSync(join(dir, 'nxp/m1_pmsm_appconfig.h'), 'utf8');
  const st = ['pmsm_motor_parameters.h', 'drive_parameters.h', 'power_stage_parameters.h', 'parameters_conversion.h',
    'parameters_conversion_g4xx.h'].map((f) => join(dir, 'st', f));
  const cpython = (files) => JSON.parse(execFileSync('python3', ['-c',
    'import json,sys; from pulab.analyses.audit import audit; print(json.dumps({"audit": audit([(f["name"], f["text"]) for f in json.load(sys.stdin)])}))'], {
    cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: JSON.stringify(files),
  }).toString());
  const page = await newPage();
  const open = async () => {
    await page.click('nav.tabs a[data-view="firmware"]');
    await page.$eval('#panel-audit', (e) => e.scrollIntoView());
  };

  await check('audit: a pasted NXP MCAT header equals CPython pulab', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await open();
    await page.fill('#panel-audit textarea[name="audit.text"]', nxp);
    await page.waitForSelector('#panel-audit [data-audit-profile="nxp"]', { timeout: 60_000 });
    const want = cpython([{ name: 'pasted.h', text: nxp }]);
    const n = await compareShown(page, want, '#panel-audit');
    assert(n >= 40, `only ${n} numbers compared`);
    // the motor its observer scales carry: Rs 0.54 Ω in the MCAT JSON
    assert(Math.abs(want.audit.design.input.motor.rs_ohm / 0.54 - 1) < 1e-3, 'Rs from the observer scales');
  });

  await check('audit: the ST file set chosen as files equals CPython pulab', async () => {
    await page.click('#panel-audit button[data-audit-clear]');
    await page.setInputFiles('#panel-audit input[name="audit.files"]', st);
    await page.waitForSelector('#panel-audit [data-audit-profile="st"]', { timeout: 60_000 });
    const want = cpython(st.map((p) => ({ name: p.split('/').pop(), text: readFileSync(p, 'utf8') })));
    const n = await compareShown(page, want, '#panel-audit');
    assert(n >= 40, `only ${n} numbers compared`);
    const c1 = await page.$eval('#panel-audit [data-key="audit.macros.C1.value"]', (e) => JSON.parse(e.dataset.value));
    assert(c1 === 477, `C1 = ${c1}`);  // (int32_t)(16384·0.35/(0.0006·20000)) = 477
  });

  await check('audit: a header of no known vendor is named at the text box', async () => {
    await page.click('#panel-audit button[data-audit-clear]');
    await page.fill('#panel-audit textarea[name="audit.text"]', '#define FOO 1\n');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="audit.text"]')?.textContent ?? '').includes('no #define'), null, { timeout: 30_000 });
    await page.fill('#panel-audit textarea[name="audit.text"]', nxp);
    await page.waitForSelector('#panel-audit [data-audit-profile="nxp"]', { timeout: 60_000 });
  });

  await check('audit: screenshots at 390/900/1366 px, zh and en', async () => {
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await open();
        await page.waitForSelector('#panel-audit [data-audit-profile="nxp"]', { timeout: 60_000 });
        const overflow = await page.$eval('#panel-audit', (e) => e.scrollWidth - e.clientWidth);
        assert(overflow <= 1, `audit panel overflows by ${overflow}px at ${w} (${lang})`);
        await (await page.$('#panel-audit')).screenshot({ path: join(SHOTS, `audit-${w}-${lang}.png`) });
      }
    }
  });
  await check('audit: the audited ST design opens as the page\'s motor (its integers equal CPython pulab\'s report)', async () => {
    await page.click('#panel-audit button[data-audit-clear]');
    await page.setInputFiles('#panel-audit input[name="audit.files"]', st);
    await page.waitForSelector('#panel-audit [data-audit-profile="st"]', { timeout: 60_000 });
    const href = await page.$eval('#panel-audit a[data-open-audit]', (e) => e.getAttribute('href'));
    const inp = JSON.parse(decodeURIComponent(href.slice(href.indexOf('#in=') + 4)));
    const want = report(inp);
    assert(inp.motor.rs_ohm === 0.35, `link input ${JSON.stringify(inp.motor)}`);
    await page.click('#panel-audit a[data-open-audit]');
    await waitValue(page, 'vendor.Rpm.value', want.vendor.Rpm.value, 0, 60_000);
  });

  await page.close();
}
