// Your code in the loop: the seed's PI block pasted in the Code view, "Use in the loop" binds it
// (error and output guessed from the names, gains and limits per axis from the report), the
// current-step plot draws it beside pulab's own integers — equal to them, and its numbers equal
// CPython's for the input the page carries; the link keeps it; "Remove" takes it out.
// Run alone: node tests/e2e/run.mjs in-loop   (E2E_NO_BUILD=1 to reuse dist/)
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function codeInLoop(ctx) {
  const { check, assert, newPage, subSrv, ready, cpython, golden, ROOT, SHOTS } = ctx;
  const PI = readFileSync(join(ROOT, 'py/pulab/ctrace/examples.py'), 'utf8').match(/_PI = """\\\n([\s\S]*?)"""/)[1];
  const seed = golden('01_seed_motor.json');
  const inp = { ...seed.input, sim: { current: { axis: 'q' } } };
  const url = `${subSrv.url}?code=${encodeURIComponent(PI)}#in=${encodeURIComponent(JSON.stringify(inp))}`;
  const p = await newPage({ context: { viewport: { width: 1366, height: 900 } } });
  const hashInput = () => p.evaluate(() => JSON.parse(decodeURIComponent(/#in=([^&]*)/.exec(location.hash)[1])));
  const codeKeys = () => p.$$eval('#panel-current [data-key^="sim.current.code."][data-value]', (els) => els.map((e) => [e.dataset.key, JSON.parse(e.dataset.value)]));

  await check('code-in-loop: the seed PI is bound by name and drawn beside pulab\'s integers, equal to them and to CPython', async () => {
    await p.goto(url);
    await ready(p);
    await p.click('nav.tabs a[data-view="firmware"]');
    await p.waitForSelector('#panel-code select[name="loop.output"]', { timeout: 60_000 });
    const picked = await p.$$eval('#panel-code .code-loop select', (els) => Object.fromEntries(els.map((e) => [e.name, e.value])));
    assert(picked['loop.error'] === 'pm_error_id' && picked['loop.output'] === 'pm_ud' && picked['loop.feedback'] === '' && picked['loop.scale'] === 'inovance',
      `guessed binding ${JSON.stringify(picked)}`);
    await p.click('#panel-code .code-loop-use');
    await p.waitForSelector('#panel-code .code-loop-active', { timeout: 30_000 });
    const carried = await hashInput();
    const code = carried.sim.current.code;
    assert(code.text === PI && code.error === 'pm_error_id' && code.output === 'pm_ud', 'the link carries the binding');
    assert(JSON.stringify(code.set.pm_kp_d) === JSON.stringify({ d: 'current_pi.d.pm_kp', q: 'current_pi.q.pm_kp' }) && !('pm_integral_d' in code.set),
      `per-axis gains from the report, the integrator from 0: ${JSON.stringify(code.set)}`);
    await p.click('nav.tabs a[data-view="loops"]');
    await p.waitForSelector('#panel-current [data-key="sim.current.code.metrics.vs_fixed_max_abs_a"][data-value]', { timeout: 60_000 });
    const want = cpython(carried).sim.current.code;
    const shown = await codeKeys();
    const expect = (k) => k.split('.').slice(3).reduce((o, x) => o[x], want);
    const bad = shown.filter(([k, v]) => (typeof v === 'number' && !Number.isInteger(v) ? Math.abs(v - expect(k)) > 1e-12 * Math.abs(expect(k)) : v !== expect(k)));
    assert(shown.length >= 9 && bad.length === 0, `${shown.length} numbers, differing ${JSON.stringify(bad)}`);
    assert(want.metrics.vs_fixed_max_abs_a === 0, 'the pasted C equals pulab\'s Inovance integers');
    await p.$eval('#panel-current .figure', (e) => e.scrollIntoView({ block: 'center' }));
    await p.waitForSelector('#panel-current .plot-host .main-svg', { timeout: 30_000 });
    await p.waitForFunction(() => [...document.querySelectorAll('#panel-current .legendtext')].some((x) => x.textContent.startsWith('your code')), null, { timeout: 30_000 });
    await p.waitForTimeout(300);
    await p.screenshot({ path: join(SHOTS, 'code-in-loop-1366-en.png') });
  });

  await check('code-in-loop: the loop box and the current plot at 390/900/1366 px, zh and en, without overflow', async () => {
    for (const lang of ['zh', 'en']) {
      for (const w of [390, 900, 1366]) {
        await p.setViewportSize({ width: w, height: 900 });
        await p.click(`button[data-lang="${lang}"]`);
        await p.$eval('#panel-current .figure', (e) => e.scrollIntoView({ block: 'center' }));
        await p.waitForSelector('#panel-current .plot-host .main-svg', { timeout: 30_000 });
        for (const id of ['#panel-current', '#panel-code']) {
          const over = await p.$eval(id, (e) => e.scrollWidth - e.clientWidth);
          assert(over <= 1, `${id} overflows by ${over} px at ${w} (${lang})`);
        }
        await (await p.$('#panel-current')).screenshot({ path: join(SHOTS, `code-in-loop-current-${w}-${lang}.png`) });
      }
    }
    await p.setViewportSize({ width: 1366, height: 900 });
  });

  await check('code-in-loop: the link keeps the routine in the loop; "Remove from the loop" takes it out', async () => {
    await p.reload();
    await ready(p);
    await p.click('nav.tabs a[data-view="loops"]');
    await p.waitForSelector('#panel-current [data-key="sim.current.code.metrics.rise_time_s"][data-value]', { timeout: 60_000 });
    await p.click('nav.tabs a[data-view="firmware"]');
    await p.waitForSelector('#panel-code .code-loop-remove', { timeout: 60_000 });
    await p.click('#panel-code .code-loop-remove');
    await p.waitForFunction(() => !/%22code%22/.test(location.hash), null, { timeout: 30_000 });
    await p.click('nav.tabs a[data-view="loops"]');
    await p.waitForSelector('#panel-current [data-key="sim.current.metrics.fixed.rise_time_s"][data-value]', { timeout: 60_000 });
    await p.waitForFunction(() => !document.querySelector('#panel-current [data-key^="sim.current.code."]'), null, { timeout: 30_000 });
  });
  await check('code-in-loop: a binding without feedback or error is named by pulab at the Code view and the plot', async () => {
    await p.click('nav.tabs a[data-view="firmware"]');
    await p.waitForSelector('#panel-code select[name="loop.error"]', { timeout: 60_000 });
    await p.selectOption('#panel-code select[name="loop.error"]', '');
    await p.click('#panel-code .code-loop-use');
    await p.waitForSelector('#panel-code .code-loop-err', { timeout: 60_000 });
    const msg = await p.$eval('#panel-code .code-loop-err', (e) => e.textContent);
    assert(msg.startsWith('sim.current.code.feedback: bind the measured current'), msg);
    await p.click('nav.tabs a[data-view="loops"]');
    assert((await p.$eval('#panel-current .sim-code-err', (e) => e.textContent)) === msg, 'the same message at the plot');
  });
  await p.context().close();
}
