// The board: a share link with a board shows its chain equal to CPython pulab, the form's board
// fields recompute it (display units converted exactly), a conflicting entry is shown at its field,
// and the view is looked at in zh and en at 390/900/1366 px.
import { join } from 'node:path';

export default async function board({ check, assert, newPage, subSrv, ready, waitValue, valueOf, cpython, golden, compareShown, SHOTS }) {
  const seed = golden('01_seed_motor.json');
  const TI = { current: { shunt_ohm: 0.007, gain: 10 }, bus: { r_top_ohm: 82000, r_bottom_ohm: 4990 },
    pwm: { clock_hz: 100e6, freq_hz: 10000, deadtime_s: 2e-7 } };
  const inp = { ...seed.input, board: TI };
  const page = await newPage();

  await check('board: a share link with a board shows every chain number CPython pulab computes', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(inp))}`);
    await ready(page);
    await page.click('nav.tabs a[data-view="firmware"]');
    await page.waitForSelector('#panel-board [data-key="board.current.max_a"][data-value]', { timeout: 30_000 });
    const want = cpython(inp);
    const n = await compareShown(page, want, '#panel-board');
    assert(n >= 15, `only ${n} board numbers compared`);
    assert(Math.abs((await valueOf(page, 'board.bus.max_v')) - 57.52845691) < 1e-7, 'TI bus full scale');
    assert((await valueOf(page, 'board.pwm.period_register')) === 5000, 'TBPRD');
  });

  await check('board: the chosen firmware\'s header constants for the board equal CPython pulab', async () => {
    const st = { ...inp, conventions: { firmware: 'st' }, board: { ...TI, pwm: { clock_hz: 170e6, freq_hz: 20000, deadtime_s: 2e-6 } } };
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(st))}`);
    await ready(page);
    await page.click('nav.tabs a[data-view="firmware"]');
    const want = cpython(st).profiles.st;
    assert(want.board.includes('DEAD_TIME_COUNTS') && want.constants.DEAD_TIME_COUNTS.value === 298, 'ST DTG code');
    for (const k of want.board) {
      const sel = `#panel-board [data-mirror-of="profiles.st.constants.${k}.value"]`;
      await page.waitForSelector(sel, { timeout: 30_000 });
      const got = Number(await page.$eval(sel, (e) => e.getAttribute('data-value')));
      assert(got === want.constants[k].value, `${k}: page ${got}, CPython ${want.constants[k].value}`);
    }
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(inp))}`);
    await ready(page);
  });

  await check('board: the form recomputes the chain; a shunt typed in mΩ is exact', async () => {
    await page.click('nav.tabs a[data-view="firmware"]');
    const box = 'input[name="board.current.shunt_ohm"]';
    await page.$eval(box, (e) => e.closest('details')?.setAttribute('open', ''));
    await page.fill(box, '3.5');  // mΩ, the field's first display unit
    await page.fill('input[name="board.current.gain"]', '11');
    const want = cpython({ ...seed.input, board: { ...TI, current: { shunt_ohm: 0.0035, gain: 11 } } });
    await waitValue(page, 'board.current.counts_per_a', want.board.current.counts_per_a);
    assert(Math.round(want.board.current.counts_per_a * 10) / 10 === 47.8, 'hoverboard 47.8 counts/A');
  });

  await check('board: a largest current typed with a shunt is shown at its field', async () => {
    await page.fill('input[name="board.current.max_a"]', '20');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="board.current.max_a"]')?.textContent ?? '').length > 0, null, { timeout: 30_000 });
    await page.fill('input[name="board.current.max_a"]', '');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="board.current.max_a"]')?.textContent ?? '') === '', null, { timeout: 30_000 });
  });

  await check('board: screenshots at 390/900/1366 px, zh and en', async () => {
    await page.goto(`${subSrv.url}#in=${encodeURIComponent(JSON.stringify(inp))}`);
    await ready(page);
    for (const lang of ['en', 'zh']) {
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.click(`button[data-lang="${lang}"]`);
        await page.click('nav.tabs a[data-view="firmware"]');
        await page.$eval('#panel-board', (e) => e.scrollIntoView());
        const overflow = await page.$eval('#panel-board', (e) => e.scrollWidth - e.clientWidth);
        assert(overflow <= 1, `board panel overflows by ${overflow}px at ${w} (${lang})`);
        await (await page.$('#panel-board')).screenshot({ path: join(SHOTS, `board-${w}-${lang}.png`) });
      }
    }
  });
  await page.close();
}
