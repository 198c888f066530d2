// "Your code", Prove mode: a PI routine proved over ranges of its inputs shows the same verdicts
// and proven ranges as CPython's `pulab trace --prove`; a counterexample loads into the trace,
// where the statement fails; a bad range is reported at its field; Cancel stops a long proof;
// screenshots at 390/900/1366 px in zh and en.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function codeProve(ctx) {
  const { check, assert, newPage, ready, valueOf, subSrv, ROOT, SHOTS } = ctx;
  const PI = readFileSync(join(ROOT, 'tests/oracle/prove_units/pi_saturated.c'), 'utf8');
  const RANGES = { e: [-4096, 4096], kp: [0, 8192], ki: [0, 1024], '*integ': [-32768, 32767] };
  const cli = (args, input) => {
    try {
      return execFileSync('python3', ['-m', 'pulab', 'trace', '-', ...args],
        { cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input }).toString();
    } catch (e) {
      if (e.status === 1) return e.stdout.toString(); // violated or unknown: the JSON is there
      throw e;
    }
  };
  const page = await newPage();
  const url = (code, entry, lang = 'en') => `${subSrv.url}?${new URLSearchParams({ code, target: 'arm', vs: '', entry, lang })}`;
  const open = async () => {
    await page.$eval('#panel-code', (e) => e.scrollIntoView());
    await page.waitForSelector('details.code-prove');
    await page.$eval('details.code-prove', (d) => { d.open = true; });
  };
  const fill = async (ranges) => {
    for (const [name, [lo, hi]] of Object.entries(ranges)) {
      await page.waitForSelector(`input[name="range.${name}.0"]`);
      await page.fill(`input[name="range.${name}.0"]`, String(lo));
      await page.fill(`input[name="range.${name}.1"]`, String(hi));
    }
  };
  const prove = async () => {
    await page.evaluate(() => delete document.documentElement.dataset.codeProveDone);
    await page.click('button.run-code-prove');
    await page.waitForFunction(() => document.documentElement.dataset.codeProveDone !== undefined, null, { timeout: 120_000 });
  };

  await check('code-prove: an input without a range is fixed at its traced value, as the CLI keeps --set', async () => {
    await page.goto(url(PI, 'pi_saturated'));
    await ready(page);
    await page.fill('input[name="set.kp"]', '16384');
    await page.fill('input[name="set.ki"]', '-7');
    await open();
    for (const n of ['kp', 'ki']) {
      const v = await page.$eval(`input[name="range.${n}.0"]`, (e) => e.value);
      assert(v === '', `range.${n} starts empty, got "${v}"`);
    }
    await page.waitForFunction(() => document.querySelector('[data-fixed-for="kp"]')?.textContent.includes('16384'));
    await fill({ e: [-4096, 4096], '*integ': [-32768, 32767] });
    await fill({ ki: ['', ''] }); // an emptied box means fixed too
    await prove();
    const box = await page.$$eval('[data-box-for]', (es) => es.map((e) => e.dataset.boxFor).sort());
    assert(JSON.stringify(box) === JSON.stringify(['*integ', 'e']), `box lists exactly the ranged inputs, got ${box}`);
    assert(await valueOf(page, 'code.prove.set.kp') === 16384 && await valueOf(page, 'code.prove.set.ki') === -7, 'kp, ki fixed at their traced values');
    const want = JSON.parse(cli(['--target', 'arm', '--entry', 'pi_saturated', '--prove', '--budget', '300',
      '--range', 'e=-4096:4096', '--range', '*integ=-32768:32767', '--set', 'kp=16384', '--set', 'ki=-7'], PI));
    assert(await page.evaluate(() => document.documentElement.dataset.codeProveDone) === want.verdict, `overall verdict ${want.verdict}`);
    for (const [i, s] of want.statements.entries()) {
      const v = await page.$eval(`[data-verdict-for="${i}"]`, (e) => e.className);
      assert(v.includes(`pr-${s.verdict}`), `${s.code}: page ${v}, CPython ${s.verdict}`);
    }
  });

  await check('code-prove: the PI routine\'s verdicts and ranges equal CPython\'s pulab trace --prove', async () => {
    await page.goto(url(PI, 'pi_saturated'));
    await ready(page);
    await open();
    await fill(RANGES);
    await prove();
    // the page stops at the first round that decides every statement: the CLI with that budget
    const want = JSON.parse(cli(['--target', 'arm', '--entry', 'pi_saturated', '--prove', '--budget', '300',
      ...Object.entries(RANGES).flatMap(([k, [a, b]]) => ['--range', `${k}=${a}:${b}`])], PI));
    assert(want.verdict === 'violated', `CLI verdict ${want.verdict}`);
    assert(await page.evaluate(() => document.documentElement.dataset.codeProveDone) === want.verdict, 'overall verdict');
    for (const [i, s] of want.statements.entries()) {
      const v = await page.$eval(`[data-verdict-for="${i}"]`, (el) => el.className.match(/pr-(\w+)/)[1]);
      assert(v === s.verdict, `${s.code}: page ${v}, CPython ${s.verdict}`);
      if (s.range) {
        const lo = await valueOf(page, `code.prove.statements.${i}.range.0`);
        const hi = await valueOf(page, `code.prove.statements.${i}.range.1`);
        assert(lo === s.range[0] && hi === s.range[1], `${s.code}: page [${lo}, ${hi}], CPython ${s.range}`);
      }
    }
  });

  await check('code-prove: the counterexample loads into the trace, where int16_t out = u; converts', async () => {
    const i = await page.$eval('button.code-prove-load', (b) => Number(b.dataset.loadCe));
    await page.click('button.code-prove-load');
    const want = JSON.parse(cli(['--target', 'arm', '--entry', 'pi_saturated', '--prove', '--budget', '300',
      ...Object.entries(RANGES).flatMap(([k, [a, b]]) => ['--range', `${k}=${a}:${b}`])], PI));
    const cx = want.statements[i].counterexample;
    for (const [name, v] of Object.entries(cx)) {
      await page.waitForFunction(([n, x]) => document.querySelector(`input[name="set.${n}"]`)?.value === String(x), [name, v]);
    }
    const traced = JSON.parse(cli(['--target', 'arm', '--entry', 'pi_saturated',
      ...Object.entries(cx).flatMap(([k, v]) => ['--set', `${k}=${v}`])], PI));
    const k = traced.steps.findIndex((s) => s.code.startsWith('int16_t out = u;'));
    assert(k >= 0 && traced.steps[k].flags.includes('conversion'), 'the CLI trace shows the conversion');
    await page.waitForFunction(([key, v]) => {
      const e = document.querySelector(`[data-key="${key}"][data-value]`);
      return e && e.dataset.value === String(v);
    }, [`code.arm.steps.${k}.value`, traced.steps[k].value], { timeout: 30_000 });
  });

  await check('code-prove: a bad range is shown at its field', async () => {
    for (const bad of ['abc', '1.5']) {
      await fill({ e: [bad, 10] });
      await prove();
      const msg = await page.$eval('[data-err-for="range.e"]', (e) => e.textContent);
      assert(msg.includes(bad), `the message at range.e quotes the bad end "${bad}": ${msg}`);
    }
    await fill(RANGES);
  });

  await check('code-prove: // @q auto proposes the Q CPython proposes', async () => {
    const GAIN = 'int16_t gain(int16_t x, int16_t k) { // @q k auto\n  int32_t p = (int32_t)x * k;\n  int16_t y = p >> 12; // @q y auto\n  return y;\n}\n';
    await page.goto(url(GAIN, 'gain'));
    await ready(page);
    await open();
    await page.waitForSelector('input[name="range.k.0"]');
    await fill({ x: [-32768, 32767], k: ['-1.5', '2.0'] });
    await prove();
    const want = JSON.parse(cli(['--target', 'arm', '--entry', 'gain', '--prove', '--budget', '300',
      '--range', 'x=-32768:32767', '--range', 'k=-1.5:2.0'], GAIN));
    assert(want.proposals.k.q === 11, `CLI proposes Q${want.proposals.k.q}`);
    const text = await page.$eval('[data-proposal-for="k"]', (e) => e.textContent);
    assert(text.includes('Q11') && text.includes(String(want.proposals.k.max_error)), text);
    // a local marked auto: what its stores compute and the bits its word has to spare
    const y = want.proposals.y;
    assert(y.local && y.shift >= 0, JSON.stringify(y));
    const local = await page.$eval('[data-proposal-for="y"]', (e) => e.textContent);
    assert(local.includes(`${y.computed[0]} … ${y.computed[1]}`) && local.includes(`${y.shift} more`), local);
    for (const lang of ['en', 'zh']) {
      if (lang === 'zh') {
        await page.goto(url(GAIN, 'gain', 'zh'));
        await ready(page);
        await open();
        await fill({ x: [-32768, 32767], k: ['-1.5', '2.0'] });
        await prove();
      }
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.$eval('.code-prove-proposals', (e) => e.scrollIntoView({ block: 'center' }));
        await page.waitForTimeout(300);
        await page.screenshot({ path: join(SHOTS, `code-prove-proposals-${lang}-${w}.png`) });
      }
      await page.setViewportSize({ width: 1366, height: 768 });
    }
  });

  await check('code-prove: editing the code after a proof removes its verdicts (they were of the old code)', async () => {
    await page.goto(url(PI, 'pi_saturated'));
    await ready(page);
    await open();
    await fill(RANGES);
    await prove();
    await page.waitForSelector('.code-prove .pr-overall');
    await page.fill('textarea[name="code"]', PI.replace('>> 12', '>> 2'));
    await page.waitForFunction(() => !document.querySelector('.code-prove .pr-overall') && !document.querySelector('table.code-prove-table'), null, { timeout: 15_000 });
  });

  await check('code-prove: Cancel stops a long proof', async () => {
    const LOOP = 'int32_t acc(int16_t x, int16_t n) {\n  int32_t s = 0;\n  for (int16_t i = 0; i < n; i++)\n    s += x;\n  return s;\n}\n';
    await page.goto(url(LOOP, 'acc'));
    await ready(page);
    await open();
    await fill({ x: [-1000, 1000], n: [0, 30000] });
    await page.evaluate(() => delete document.documentElement.dataset.codeProveDone);
    await page.click('button.run-code-prove');
    await page.waitForTimeout(300);
    await page.click('button.cancel-code-prove');
    await page.waitForFunction(() => document.documentElement.dataset.codeProveDone !== undefined, null, { timeout: 60_000 });
    assert(await page.evaluate(() => document.documentElement.dataset.codeProveDone) === 'cancelled', 'cancelled');
  });

  await check('code-prove: screenshots 390/900/1366 px, zh and en', async () => {
    for (const lang of ['zh', 'en']) {
      await page.goto(url(PI, 'pi_saturated', lang));
      await ready(page);
      await open();
      await fill(RANGES);
      await prove();
      for (const w of [390, 900, 1366]) {
        await page.setViewportSize({ width: w, height: 900 });
        await page.$eval('details.code-prove', (e) => e.scrollIntoView());
        await page.waitForTimeout(300);
        await page.screenshot({ path: join(SHOTS, `code-prove-${lang}-${w}.png`) });
      }
      await page.setViewportSize({ width: 1366, height: 768 });
    }
  });
  await page.context().close();
}
