// "Your code" with a whole file: a file of functions opens on the last one defined,
// the function menu lists them, a struct field and an out-parameter are inputs and results, a
// call's statements open under it, the CLI (--entry) agrees; screenshots in both languages.
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';

const FILE = `#include <stdint.h>
typedef struct { int16_t kp; int16_t ki; int32_t integ; } pi_t;

static int32_t clamp(int32_t v, int32_t lo, int32_t hi)
{
  return v < lo ? lo : (v > hi ? hi : v);
}

int16_t pi_step(pi_t *p, int16_t err, int16_t *sat)
{
  int32_t out;
  p->integ = clamp(p->integ + (int32_t)p->ki * err, -1000000, 1000000);
  out = ((int32_t)p->kp * err + p->integ) >> 12;
  *sat = out != clamp(out, -32768, 32767);
  return (int16_t)clamp(out, -32768, 32767);
}
`;

// A header of a math block as TI keeps them: a struct typedef and a statement macro over it.
const MACRO_FILE = `typedef struct { long ia; long ib; long al; long be; } ALBE;
#define ALBE_RUN(w)                                       \\
    w.al = w.ia;                                          \\
    w.be = _IQmpy((w.ia + (w.ib << 1)), _IQ(0.57735026918963));
`;

export default async function codeFile(ctx) {
  const { check, assert, newPage, ready, waitValue, subSrv, ROOT, SHOTS } = ctx;
  const cli = (target, set) => JSON.parse(execFileSync('python3',
    ['-m', 'pulab', 'trace', '-', '--target', target, '--entry', 'pi_step', '--zero-unset',
      ...Object.entries(set).flatMap(([k, v]) => ['--set', `${k}=${v}`])],
    { cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: FILE }).toString());
  const set = { err: 1000, 'p.kp': 8000, 'p.ki': 300, 'p.integ': 50000 };
  const url = `${subSrv.url}?code=${encodeURIComponent(FILE)}&target=c28x&vs=arm&${Object.entries(set).map(([k, v]) => `set.${encodeURIComponent(k)}=${v}`).join('&')}`;
  const page = await newPage();

  await check('code file: the last function runs, its menu lists both, fields and results agree with the CLI', async () => {
    await page.goto(url);
    await ready(page);
    await page.$eval('#panel-code', (e) => e.scrollIntoView());
    await page.waitForSelector('[data-key="code.c28x.vars.return.value"][data-value]', { timeout: 60_000 });
    const options = await page.$$eval('select[name="entry"] option', (els) => els.map((e) => e.value));
    assert(JSON.stringify(options) === JSON.stringify(['', 'clamp', 'pi_step']), `menu ${options}`);
    assert((await page.$eval('select[name="entry"]', (e) => e.value)) === 'pi_step', 'the last function chosen');
    for (const name of ['err', 'p.kp', 'p.ki', 'p.integ']) assert(await page.$(`input[name="set.${name}"]`), `field set.${name}`);
    for (const target of ['c28x', 'arm']) {
      const want = cli(target, set);
      for (const name of ['return', 'p.integ', '*sat']) await waitValue(page, `code.${target}.vars.${name}.value`, want.vars[name].value);
    }
    // c28x: 8000·1000 in a 32-bit long, >> 12 = 2075 with the integrator; both targets agree here
    assert(await page.$('details.code-call'), 'a call\'s statements under it');
    await page.$eval('details.code-call', (e) => { e.open = true; e.scrollIntoView(); });
    await page.screenshot({ path: join(SHOTS, 'code-file-1366-en-call.png') });
  });

  for (const [width, locale] of [[390, 'zh-CN'], [900, 'en-US'], [1366, 'zh-CN'], [1366, 'en-US']]) {
    await check(`code file: screenshot ${width}px ${locale}`, async () => {
      const p = await newPage({ locale, context: { viewport: { width, height: 900 } } });
      await p.goto(url);
      await p.click('nav.tabs a[data-view="firmware"]'); // the code panel's tab
      await p.waitForSelector('[data-key="code.arm.vars.return.value"][data-value]', { timeout: 60_000 });
      await p.$eval('#panel-code', (e) => e.scrollIntoView());
      await p.screenshot({ path: join(SHOTS, `code-file-${width}-${locale}.png`) });
      const overflow = await p.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
      assert(overflow <= 1, `page wider than the viewport by ${overflow}px`);
      await p.context().close();
    });
  }
  await check('code file: a header of macros opens on its macro, run on an object of the struct it uses', async () => {
    const mset = { 'w.ia': 1 << 23, 'w.ib': -(1 << 21) };
    const want = JSON.parse(execFileSync('python3', ['-m', 'pulab', 'trace', '-', '--target', 'c28x', '--entry', 'ALBE_RUN',
      ...Object.entries(mset).flatMap(([k, v]) => ['--set', `${k}=${v}`])],
    { cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: MACRO_FILE }).toString());
    const murl = `${subSrv.url}?code=${encodeURIComponent(MACRO_FILE)}&target=c28x&${Object.entries(mset).map(([k, v]) => `set.${encodeURIComponent(k)}=${v}`).join('&')}`;
    for (const [width, locale] of [[390, 'zh-CN'], [900, 'en-US'], [1366, 'en-US'], [1366, 'zh-CN']]) {
      const p = await newPage({ locale, context: { viewport: { width, height: 900 } } });
      await p.goto(murl);
      await p.click('nav.tabs a[data-view="firmware"]');
      await p.waitForSelector('[data-key="code.c28x.vars.w.be.value"][data-value]', { timeout: 60_000 });
      const labels = await p.$$eval('select[name="entry"] option', (els) => els.map((e) => e.textContent));
      assert(labels.includes('ALBE_RUN(…)'), `menu ${labels}`);
      assert((await p.$eval('select[name="entry"]', (e) => e.value)) === 'ALBE_RUN', 'the macro chosen');
      await waitValue(p, 'code.c28x.vars.w.be.value', want.vars['w.be'].value);
      await waitValue(p, 'code.c28x.vars.w.al.value', want.vars['w.al'].value);
      await p.$eval('#panel-code', (e) => e.scrollIntoView());
      await p.screenshot({ path: join(SHOTS, `code-macro-${width}-${locale}.png`) });
      const overflow = await p.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
      assert(overflow <= 1, `page wider than the viewport by ${overflow}px`);
      await p.context().close();
    }
  });
  await page.context().close();
}
