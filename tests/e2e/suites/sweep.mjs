// The family view on the page: a sweep of the seed motor shows the exact LD wrap and
// m_BaseL = 0 boundaries CPython's `pulab sweep` finds; the page stays responsive while it runs;
// cancel stops it; a worst case opens as the current motor; a 2-D map draws; a batch of the
// 1,000-motor catalogue gives the same CSV as `pulab batch`, bad rows reported.
import { execFileSync, spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function sweep(ctx) {
  const { check, assert, newPage, subSrv, ready, waitValue, valueOf, cpython, golden, ROOT, SHOTS, timings } = ctx;
  const seed = golden('01_seed_motor.json');
  const py = (args, input) => execFileSync('python3', ['-m', 'pulab', ...args], {
    cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input, maxBuffer: 64 << 20,
  }).toString();
  const page = await newPage();
  const setAxis = async (which, path, start, stop, n, scale) => {
    await page.selectOption(`select[name="sweep.${which}.path"]`, path);
    await page.fill(`input[name="sweep.${which}.start"]`, String(start));
    await page.fill(`input[name="sweep.${which}.stop"]`, String(stop));
    await page.fill(`input[name="sweep.${which}.n"]`, String(n));
    await page.selectOption(`select[name="sweep.${which}.scale"]`, scale);
  };
  const runSweep = async (total) => {
    await page.click('button.run-sweep');
    await page.waitForFunction((n) => document.documentElement.dataset.sweepDone === String(n), total, { timeout: 60_000 });
  };

  await check('sweep: the seed motor\'s LD wrap and m_BaseL = 0 boundaries equal CPython\'s, to the double', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-sweep', (e) => e.scrollIntoView());
    await setAxis('x', 'motor.rated_current_a', 1, 200, 400, 'linear');
    await runSweep(400);
    const want = JSON.parse(py(['sweep', '-', '--x', 'motor.rated_current_a=1:200:400', '--format', 'json'], JSON.stringify(seed.input)));
    const shown = await page.$$eval('table.sweep-bounds [data-key$=".at"]', (els) => els.map((e) => JSON.parse(e.dataset.value)));
    const wantAt = want.summary.boundaries.map((b) => b.at);
    assert(JSON.stringify(shown) === JSON.stringify(wantAt), `page ${shown} vs CPython ${wantAt}`);
    assert(wantAt.includes(69.47500000000001) && wantAt.includes(125.05499999999999), `LD boundaries ${wantAt}`);
    await page.waitForSelector('.sweep-1d .main-svg', { timeout: 30_000 });
    await page.$eval('.sweep-fig', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, 'sweep-1d.png') });
  });

  await check('sweep: the page answers typing while a 10,000-point sweep runs; cancel stops it', async () => {
    // The most points an axis takes: on a loaded machine 3,000 were done before Cancel was pressed.
    await setAxis('x', 'motor.rated_voltage_v', 0.5, 1000, 10000, 'log');
    const want = cpython({ ...seed.input, motor: { ...seed.input.motor, rs_ohm: 2.2 } });
    await page.evaluate(() => delete document.documentElement.dataset.sweepDone);
    await page.click('button.run-sweep');
    await page.waitForFunction(() => Number(document.querySelector('progress.sweep-progress')?.value ?? 0) > 0, null, { timeout: 30_000 });
    const t0 = Date.now();
    await page.fill('input[name="motor.rs_ohm"]', '2.2');
    await waitValue(page, 'vendor.Rpm.value', want.vendor.Rpm.value, 0, 20_000);
    timings.sweep_typing_ms = Date.now() - t0;
    console.log(`      typing → new Rpm during the sweep: ${timings.sweep_typing_ms} ms`);
    assert(!(await page.isDisabled('button.cancel-sweep')), 'the sweep ended before Cancel was pressed');
    await page.click('button.cancel-sweep');
    await page.waitForFunction(() => document.documentElement.dataset.sweepDone !== undefined && document.querySelector('button.run-sweep:not([disabled])'), null, { timeout: 30_000 });
    const done = Number(await page.evaluate(() => document.documentElement.dataset.sweepDone));
    assert(done > 0 && done < 10000, `cancelled after ${done} points`);
    await page.fill('input[name="motor.rs_ohm"]', '1.5');
    await waitValue(page, 'vendor.Rpm.value', 15022);
  });

  await check('sweep: a worst case opens as the current motor', async () => {
    await setAxis('x', 'motor.rated_current_a', 1, 60, 60, 'linear');
    await runSweep(60);
    const link = await page.$('a[data-open-worst="vendor.Rpm"]');
    assert(link, 'no worst-case link for vendor.Rpm');
    const value = await page.$eval('[data-key="sweep.summary.worst.vendor.Rpm.value"]', (e) => JSON.parse(e.dataset.value));
    await link.click();
    await waitValue(page, 'vendor.Rpm.value', value, 0, 20_000);
    const amps = await page.$eval('input[name="motor.rated_current_a"]', (e) => e.value);
    assert(Number(amps) > 6.5, `current in the form ${amps}`);
    assert((await valueOf(page, 'vendor.Rpm.value')) === value, 'Rpm of the opened motor');
  });

  await check('sweep: 2-D map of voltage × current draws, boundaries along both axes', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(seed.input))}`);
    await ready(page);
    await page.$eval('#panel-sweep', (e) => e.scrollIntoView());
    await page.check('input[name="sweep.twoD"]');
    await setAxis('x', 'motor.rated_voltage_v', 1, 100, 24, 'log');
    await setAxis('y', 'motor.rated_current_a', 1, 150, 16, 'log');
    await runSweep(24 * 16);
    await page.waitForSelector('.sweep-2d .main-svg', { timeout: 30_000 });
    const axes = await page.$$eval('table.sweep-bounds tbody tr', (rows) => rows.length);
    assert(axes > 5, `${axes} boundaries`);
    await page.$eval('.sweep-fig', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, 'sweep-2d.png') });
  });

  await check('batch: the 1,000-motor catalogue gives the same CSV as `pulab batch`, rows beyond the firmware marked', async () => {
    const file = join(ROOT, 'tests/data/motors-1000.csv');
    const cli = spawnSync('python3', ['-m', 'pulab', 'batch', file], { cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, maxBuffer: 64 << 20 });
    // Rows the Inovance firmware cannot hold still compute (their `firmware` cell says why): exit 0.
    assert(cli.status === 0, `CLI exit ${cli.status}: ${cli.stderr}`);
    const cliRows = cli.stdout.toString().trim().split('\n').map((l) => l.split(','));
    assert(cliRows[0].at(-1) === 'firmware', 'firmware is the last CSV column');
    await page.$eval('#panel-batch', (e) => e.scrollIntoView());
    const t0 = Date.now();
    await page.setInputFiles('input[name="batch.csv"]', file);
    await page.waitForFunction(() => document.documentElement.dataset.batchDone === '1000', null, { timeout: 120_000 });
    timings.batch_1000_ms = Date.now() - t0;
    const [dl] = await Promise.all([page.waitForEvent('download'), page.click('button.download-batch')]);
    const text = readFileSync(await dl.path(), 'utf8');
    assert(text === cli.stdout.toString(), 'page CSV differs from the CLI');
    const shown = await page.$$eval('table.batch-table tbody tr', (r) => r.length);
    const limitCli = cliRows.slice(1, shown + 1).filter((r) => r.at(-1)).length;
    const limitPage = await page.$$eval('table.batch-table tr.limit', (r) => r.length);
    assert(limitPage > 0 && limitPage === limitCli, `firmware-limited rows among the ${shown} shown: page ${limitPage}, CLI ${limitCli}`);
    console.log(`      1,000 rows in the page: ${timings.batch_1000_ms} ms; ${limitCli} of the first ${shown} beyond the Inovance firmware`);
    await page.screenshot({ path: join(SHOTS, 'batch.png') });
  });

  await check('sweep and batch at 390 / 900 px and in Chinese', async () => {
    for (const [w, lang] of [[390, 'en'], [900, 'zh'], [1366, 'zh']]) {
      await page.setViewportSize({ width: w, height: 900 });
      if (lang === 'zh') await page.click('.lang button:has-text("中文")').catch(() => undefined);
      await page.$eval('#panel-sweep', (e) => e.scrollIntoView());
      await page.waitForTimeout(300);
      await page.screenshot({ path: join(SHOTS, `sweep-${w}-${lang}.png`) });
      const overflow = await page.$eval('#panel-sweep', (e) => e.scrollWidth - e.clientWidth);
      assert(overflow <= 1, `sweep panel overflows by ${overflow}px at ${w}px`);
    }
  });
  await page.context().close();
}
