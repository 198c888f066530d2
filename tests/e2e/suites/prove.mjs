// The Prove view: a proof over a range of the seed motor's current shows the same verdicts and
// proven ranges as CPython's `pulab prove`; a counterexample opens as the page input and breaks
// the integer there; cancel stops the job; a bad range is reported at its row; screenshots.
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';

export default async function prove(ctx) {
  const { check, assert, newPage, subSrv, ready, waitValue, golden, ROOT, SHOTS } = ctx;
  const seed = golden('01_seed_motor.json');
  const py = (args, input) => {
    try {
      return execFileSync('python3', ['-m', 'pulab', ...args], {
        cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input, maxBuffer: 64 << 20,
      }).toString();
    } catch (e) {
      if (e.status === 1) return e.stdout.toString(); // violated or unknown: the JSON is still there
      throw e;
    }
  };
  const page = await newPage();
  const setRows = async (rows) => {
    // Remove down to one row, add as needed, then fill.
    for (let n = 0; (await page.$$('.pr-range')).length > 1; n++) {
      assert(n < 10, 'Remove leaves the rows as they were');
      await page.click('.pr-range button.pr-remove');
    }
    for (let i = 1; i < rows.length; i++) await page.click('button.pr-add');
    for (const [i, [path, lo, hi]] of rows.entries()) {
      await page.selectOption(`select[name="prove.ranges.${i}.path"]`, path);
      await page.fill(`input[name="prove.ranges.${i}.lo"]`, String(lo));
      await page.fill(`input[name="prove.ranges.${i}.hi"]`, String(hi));
    }
  };
  const runProof = async () => {
    await page.evaluate(() => delete document.documentElement.dataset.proveDone);
    await page.click('button.run-prove');
    await page.waitForFunction(() => document.documentElement.dataset.proveDone !== undefined, null, { timeout: 60_000 });
  };
  const rows = [['motor.rated_current_a', 1, 100], ['drive.base_freq_hz', 150, 300]];

  await check('prove: verdicts and proven ranges equal CPython\'s pulab prove', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-prove', (e) => e.scrollIntoView());
    await setRows(rows);
    await runProof();
    const want = JSON.parse(py(['prove', '-', ...rows.flatMap(([p, a, b]) => ['--range', `${p}=${a}:${b}`])], JSON.stringify(seed.input)));
    assert(await page.evaluate(() => document.documentElement.dataset.proveDone) === want.verdict, 'overall verdict');
    for (const [name, e] of Object.entries(want.integers)) {
      const shown = await page.$eval(`[data-verdict-for="${name}"]`, (el) => el.textContent);
      const verdict = await page.$eval(`[data-verdict-for="${name}"]`, (el) => el.className.match(/pr-(\w+)/)[1]);
      assert(verdict === e.verdict, `${name}: page ${verdict} (${shown}), CPython ${e.verdict}`);
      if (e.range) {
        const lo = await page.$eval(`[data-key="prove.integers.${name}.range.0"]`, (el) => JSON.parse(el.dataset.value));
        const hi = await page.$eval(`[data-key="prove.integers.${name}.range.1"]`, (el) => JSON.parse(el.dataset.value));
        assert(lo === e.range[0] && hi === e.range[1], `${name}: page [${lo}, ${hi}], CPython ${e.range}`);
      }
    }
    assert(want.integers['vendor.LD'].verdict === 'violated', 'the box must break LD for the next check');
    await page.$eval('.prove-table', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, 'prove-table.png') });
  });

  await check('prove: TI MotorWare\'s IQ constants, verdicts equal CPython\'s --profile ti', async () => {
    await page.selectOption('select[name="prove.profile"]', 'ti');
    const tiRows = [['motor.rated_current_a', 0.5, 100], ['motor.ld_h', 1e-5, 0.05]];
    await setRows(tiRows);
    await runProof();
    const want = JSON.parse(py(['prove', '-', '--profile', 'ti', ...tiRows.flatMap(([p, a, b]) => ['--range', `${p}=${a}:${b}`])], JSON.stringify(seed.input)));
    const names = Object.keys(want.integers);
    assert(names.length > 5 && names.every((n) => n.startsWith('profiles.ti.constants.')), `names ${names}`);
    for (const [name, e] of Object.entries(want.integers)) {
      const verdict = await page.$eval(`[data-verdict-for="${name}"]`, (el) => el.className.match(/pr-(\w+)/)[1]);
      assert(verdict === e.verdict, `${name}: page ${verdict}, CPython ${e.verdict}`);
    }
    await page.selectOption('select[name="prove.profile"]', 'inovance');
    await setRows(rows);
    await runProof();
  });

  await check('prove: NXP, ST and Microchip constants, shifts and divisors equal CPython\'s, with proposals', async () => {
    const boxes = {
      nxp: [['motor.ld_h', 1e-3, 1], ['motor.rated_current_a', 5, 200]],
      st: [['motor.rated_current_a', 1, 40], ['motor.ld_h', 1e-4, 1e-2]],
      microchip: [['motor.rated_current_a', 1, 40], ['motor.ld_h', 1e-4, 1e-2]],
    };
    for (const [profile, box] of Object.entries(boxes)) {
      await page.selectOption('select[name="prove.profile"]', profile);
      await setRows(box);
      await runProof();
      const args = ['prove', '-', '--profile', profile, '--propose', ...box.flatMap(([p, a, b]) => ['--range', `${p}=${a}:${b}`])];
      const want = JSON.parse(py(args, JSON.stringify(seed.input)));
      assert(await page.evaluate(() => document.documentElement.dataset.proveDone) === want.verdict, `${profile}: overall verdict`);
      for (const [name, e] of Object.entries(want.integers)) {
        const verdict = await page.$eval(`[data-verdict-for="${name}"]`, (el) => el.className.match(/pr-(\w+)/)[1]);
        assert(verdict === e.verdict, `${name}: page ${verdict}, CPython ${e.verdict}`);
        if (e.range) {
          const hi = await page.$eval(`[data-key="prove.integers.${name}.range.1"]`, (el) => JSON.parse(el.dataset.value));
          assert(hi === e.range[1], `${name}: page hi ${hi}, CPython ${e.range[1]}`);
        }
        if (e.verdict === 'violated') {
          const ce = JSON.parse(await page.$eval(`a[data-open-ce="${name}"]`, (a) => decodeURIComponent(a.getAttribute('href').replace(/^#in=/, ''))));
          for (const [path, lo, hi] of box) {
            const [sec, key] = path.split('.');
            assert(ce[sec][key] >= lo && ce[sec][key] <= hi, `${name}: counterexample ${path} = ${ce[sec][key]} outside the box`);
          }
          // The page's counterexample breaks the constant in CPython's report too.
          const c = JSON.parse(py(['report', '-'], JSON.stringify(ce))).profiles[profile].constants[name.split('.').pop()];
          assert(c.flags.includes('saturate') || c.flags.includes('out_of_range') || (c.value === 0 && c.ideal !== 0), `${name}: report on the counterexample: ${JSON.stringify(c)}`);
        }
      }
      await page.click('button.run-propose');
      await page.waitForSelector('.prove-proposal', { timeout: 60_000 });
      for (const [name, e] of Object.entries(want.proposal.constants)) {
        if (!e || !e.holds) continue;
        const fmt = await page.$eval(`[data-key="prove.proposal.constants.${name}.format"]`, (el) => JSON.parse(el.dataset.value));
        const err = await page.$eval(`[data-key="prove.proposal.constants.${name}.worst_error_pct"]`, (el) => JSON.parse(el.dataset.value));
        assert(fmt === e.format && err === e.worst_error_pct, `${name}: page ${fmt} ≤ ${err} %, CPython ${e.format} ≤ ${e.worst_error_pct} %`);
      }
      await page.$eval('.prove-table', (e) => e.scrollIntoView());
      await page.screenshot({ path: join(SHOTS, `prove-${profile}.png`), fullPage: false });
    }
    await page.selectOption('select[name="prove.profile"]', 'inovance');
    await setRows(rows);
    await runProof();
    // Inovance's fixed formats: the proposal is each proven integer's headroom, as CPython's.
    await page.click('button.run-propose');
    await page.waitForSelector('.prove-proposal', { timeout: 60_000 });
    const ino = JSON.parse(py(['prove', '-', '--propose', ...rows.flatMap(([p, a, b]) => ['--range', `${p}=${a}:${b}`])], JSON.stringify(seed.input))).proposal;
    const inoNames = Object.keys(ino.integers);
    assert(inoNames.length > 3, `headroom rows: ${inoNames}`);
    for (const [name, e] of Object.entries(ino.integers)) {
      const bits = await page.$eval(`[data-key="prove.proposal.integers.${name}.headroom_bits"]`, (el) => JSON.parse(el.dataset.value));
      assert(bits === e.headroom_bits, `${name}: page +${bits} bits, CPython +${e.headroom_bits}`);
    }
  });

  await check('prove: a counterexample opens as the page input, where LD breaks', async () => {
    const ce = JSON.parse(await page.$eval('a[data-open-ce="vendor.LD"]', (a) => decodeURIComponent(a.getAttribute('href').replace(/^#in=/, ''))));
    await page.click('a[data-open-ce="vendor.LD"]');
    await page.waitForFunction((v) => Number(document.querySelector('input[name="motor.rated_current_a"]')?.value) === v, ce.motor.rated_current_a, { timeout: 20_000 });
    const want = JSON.parse(py(['report', '-'], JSON.stringify(ce)));
    if (want.vendor.LD) await waitValue(page, 'vendor.LD.value', want.vendor.LD.value, 0, 20_000);
    assert(!want.vendor.LD || want.vendor.LD.flags.includes('store') || want.vendor.LD.flags.includes('wrap') || want.vendor.LD.value === 0, `LD of the counterexample: ${JSON.stringify(want.vendor.LD)}`);
  });

  await check('prove: cancel stops between integers; a bad range is reported at its row', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(seed.input))}`);
    await page.reload(); // a hash change alone keeps the page (and the panel) it had
    await ready(page);
    await page.$eval('#panel-prove', (e) => e.scrollIntoView());
    await setRows(rows);
    await page.evaluate(() => {
      delete document.documentElement.dataset.proveDone;
      document.querySelector('button.run-prove').click();
      document.querySelector('button.cancel-prove').click();
    });
    await page.waitForFunction(() => document.documentElement.dataset.proveDone === 'cancelled', null, { timeout: 30_000 });
    const note = await page.$eval('.prove-note', (e) => e.textContent);
    assert(/Cancelled after \d+ of 20/.test(note), `note: ${note}`);
    await setRows([['motor.rated_current_a', 5, 2]]);
    await page.click('button.run-prove');
    await page.waitForFunction(() => document.querySelector('[data-err-for="prove.ranges.motor.rated_current_a"]')?.textContent, null, { timeout: 30_000 });
    const err = await page.$eval('[data-err-for="prove.ranges.motor.rated_current_a"]', (e) => e.textContent);
    assert(err.includes('lo must be ≤ hi'), `error: ${err}`);
  });

  await check('prove: during a long run, keys typed into a range all land and a mouse press on Cancel stops it', async () => {
    // Nine inputs over wide ranges: a run of several seconds, its results arriving integer by integer.
    await setRows([['motor.rated_current_a', 0.01, 1000], ['motor.rated_voltage_v', 1, 1000], ['motor.ld_h', 1e-6, 1],
      ['motor.rs_ohm', 0.001, 100], ['drive.base_freq_hz', 1, 5000], ['drive.udc_v', 1, 2000],
      ['motor.bemf_v', 1, 1000], ['motor.pole_pairs', 1, 50], ['drive.ts_s', 1e-6, 0.01]]);
    await page.evaluate(() => delete document.documentElement.dataset.proveDone);
    await page.click('button.run-prove');
    // Some integers decided (several may land between two polls), the run still going.
    await page.waitForFunction(() => /^[1-9]\d* \//.test(document.querySelector('.prove-count')?.textContent ?? ''), null, { timeout: 30_000 });
    await page.click('input[name="prove.ranges.0.hi"]', { clickCount: 3 });
    await page.keyboard.type('123456', { delay: 40 });
    const typed = await page.inputValue('input[name="prove.ranges.0.hi"]');
    assert(typed === '123456', `typed 123456 during the run, the box holds "${typed}"`);
    assert(await page.evaluate(() => document.activeElement?.getAttribute('name')) === 'prove.ranges.0.hi', 'focus left the box');
    assert(await page.evaluate(() => document.documentElement.dataset.proveDone === undefined), 'the run ended before Cancel was pressed: the box is too small');
    await page.click('button.cancel-prove', { delay: 120 }); // a person's press: down, 120 ms, up
    await page.waitForFunction(() => document.documentElement.dataset.proveDone !== undefined, null, { timeout: 30_000 });
    const how = await page.evaluate(() => document.documentElement.dataset.proveDone);
    assert(how === 'cancelled', `the run ended "${how}", not cancelled`);
  });

  await check('prove: screenshots at 390/900/1366 px, zh and en', async () => {
    await setRows(rows);
    await runProof();
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await page.$eval('#panel-prove', (e) => e.scrollIntoView());
        await page.waitForTimeout(200);
        await page.screenshot({ path: join(SHOTS, `prove-${lang}-${w}.png`) });
      }
    }
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
    assert(overflow <= 1, `page scrolls sideways by ${overflow} px`);
    // A vendor profile with its proposal, in both languages and at each width.
    await page.selectOption('select[name="prove.profile"]', 'microchip');
    await setRows([['motor.rated_current_a', 1, 40], ['motor.ld_h', 1e-4, 1e-2]]);
    await runProof();
    await page.click('button.run-propose');
    await page.waitForSelector('.prove-proposal', { timeout: 60_000 });
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await page.$eval('.pr-proposal', (e) => e.scrollIntoView());
        await page.waitForTimeout(200);
        await page.screenshot({ path: join(SHOTS, `prove-vendor-${lang}-${w}.png`) });
      }
    }
    const wide = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
    assert(wide <= 1, `page scrolls sideways by ${wide} px with a proposal`);
  });
  await page.context().close();
}
