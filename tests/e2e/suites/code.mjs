// "Your code" panel: the seed's flux lines and a TI _IQmpy line traced on c28x and
// arm, inputs prefilled from the motor's raw integers, where the targets differ, bad code named
// by line:column at the field, the shareable link and the embed; screenshots in both languages.
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';

export default async function code(ctx) {
  const { check, assert, newPage, ready, valueOf, waitValue, subSrv, ROOT, SHOTS } = ctx;
  /** The same trace in CPython: python -m pulab trace (the CLI contract). */
  const cli = (src, target, set) => JSON.parse(execFileSync('python3',
    ['-m', 'pulab', 'trace', '-', '--target', target, ...Object.entries(set).flatMap(([k, v]) => ['--set', `${k}=${v}`])],
    { cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: src }).toString());
  const page = await newPage();
  const FLUX = (await import('node:fs')).readFileSync(join(ROOT, 'py/pulab/ctrace/examples.py'), 'utf8')
    .match(/_FLUX = """\\\n([\s\S]*?)"""/)[1];
  const CODE = `${FLUX}_iq err = -5000;\n_iq out = _IQmpy(err, 3L << 23);\n`;
  const SEED_RAW = { 'gMotorInfo.FreqRated01': 22000, 'gBasePar.FullFreq01': 22000, 'gMotorExtInfo.BemfVolt': 120, 'gMotorInfo.Voltage': 17 };

  await check('code: the flux example is traced with the seed motor\'s raw integers, c28x beside arm', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    await page.$eval('#panel-code', (e) => e.scrollIntoView());
    await page.waitForSelector('[data-key="code.c28x.vars.gMotorExtPer.FluxRotor.value"][data-value]', { timeout: 30_000 });
    const want = cli(FLUX, 'c28x', SEED_RAW);
    for (const [name, v] of Object.entries(want.vars)) {
      assert((await valueOf(page, `code.c28x.vars.${name}.value`)) === v.value, `${name}: page vs CLI ${v.value}`);
    }
    assert((await page.$eval('input[name="set.gMotorInfo.Voltage"]', (e) => e.placeholder)) === '17', 'Voltage prefilled from raw.Voltage');
    assert(await page.$('[data-key="code.arm.vars.m_Ulong.value"]'), 'arm column shown');
  });

  await check('code: pasted flux lines + _IQmpy line; Voltage = 6554 wraps on c28x, not on arm', async () => {
    await page.fill('textarea[name="code"]', CODE);
    await page.waitForSelector('input[name="set.gMotorInfo.Voltage"]');
    await page.fill('input[name="set.gMotorInfo.Voltage"]', '6554');
    const set = { ...SEED_RAW, 'gMotorInfo.Voltage': 6554 };
    const c28x = cli(CODE, 'c28x', set);
    const arm = cli(CODE, 'arm', set);
    assert(c28x.vars.m_Ulong.value === 122880 && arm.vars.m_Ulong.value === 7, 'the CLI shows the difference');
    await waitValue(page, 'code.c28x.vars.m_Ulong.value', 122880);
    await waitValue(page, 'code.arm.vars.m_Ulong.value', 7);
    assert((await valueOf(page, 'code.c28x.vars.out.value')) === c28x.vars.out.value, '_IQmpy on the page = CLI');
    assert(c28x.vars.out.value === -7500, '_IQmpy(-5000, 1.5 in Q24) = -7500');
    const differ = await page.$eval('.code-summary', (e) => Number(e.dataset.differ));
    assert(differ >= 2, `summary counts ${differ} differing variables`);
    assert(await page.$$eval('#panel-code tr.differs', (els) => els.some((e) => e.textContent.includes('m_Ulong'))), 'differing rows marked');
    const flags = await page.$$eval('#panel-code .flag-unsigned_wrap', (els) => els.length);
    assert(flags > 0, 'the 16-bit wrap of Voltage*10 is flagged');
    await page.$eval('#panel-code', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, 'code-1366-en.png') });
    await page.$eval('#panel-code table.code-steps', (e) => e.scrollIntoView());
    await page.screenshot({ path: join(SHOTS, 'code-1366-en-steps.png') });
  });

  await check('code: a code error clears the previous trace and its verdict', async () => {
    await page.waitForSelector('#panel-code .code-summary');
    await page.fill('textarea[name="code"]', `${CODE}\nint16_t = ;\n`);
    await page.waitForFunction(() => document.querySelector('#panel-code [data-err-for="code"]')?.textContent !== '');
    await page.waitForFunction(() => !document.querySelector('#panel-code .code-summary') && !document.querySelector('#panel-code table.code-steps'),
      null, { timeout: 15_000 });
    await page.fill('textarea[name="code"]', CODE);
    await page.waitForSelector('#panel-code .code-summary');
  });

  await check('code: equal final values with an intermediate difference do not read "all equal"', async () => {
    // ref - fb overflows int on c28x (-1) and is 65535 on arm; the cast makes out -1 on both.
    const SUB = 'int16_t out;\nvoid f(int16_t ref, int16_t fb) {\n  out = (int16_t)(ref - fb);\n}\n';
    const p = await newPage();
    await p.goto(`${subSrv.url}?code=${encodeURIComponent(SUB)}&target=c28x&vs=arm&entry=f&set.ref=32767&set.fb=-32768`);
    await p.click('nav.tabs a[data-view="firmware"]');
    await p.waitForSelector('[data-key="code.arm.vars.out.value"][data-value="-1"]', { timeout: 60_000 });
    const { n, text } = await p.$eval('#panel-code .code-summary', (e) => ({ n: e.dataset.stepsDiffer, text: e.textContent }));
    assert(n === '1' && text.includes('3:'), `one differing statement, at line 3: ${n} "${text}"`);
    await p.context().close();
  });

  await check('code: the PI example with the report\'s gains and step example gives the report\'s vendor PI output', async () => {
    await page.selectOption('select[name="example"]', 'pi');
    const want = ctx.cpython(ctx.golden('01_seed_motor.json').input).current_pi.step_example.trace.at(-1).value;
    await waitValue(page, 'code.c28x.vars.pm_ud.value', want, 0, 15_000);
    assert((await page.$eval('input[name="set.pm_kp_d"]', (e) => e.placeholder)) !== '', 'pm_kp_d prefilled from current_pi.d.pm_kp');
  });

  await check('code: bad code is named by line:column at the field, no crash', async () => {
    await page.fill('textarea[name="code"]', 'long a = 1;\nlong b = a +;\n');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="code"]')?.textContent ?? '').includes('2:13'), null, { timeout: 10_000 });
    assert(await page.$('.code-caret'), 'the line with a caret');
    await page.fill('textarea[name="code"]', 'long a = 1;\nlong b = a / (a - 1);\n');
    await page.waitForFunction(() => (document.querySelector('[data-err-for="code"]')?.textContent ?? '').includes('2:14'), null, { timeout: 10_000 });
  });

  await check('code: share link reproduces the code, target and inputs; ?embed=code shows only the panel', async () => {
    await page.fill('textarea[name="code"]', CODE);
    await page.fill('input[name="set.gMotorInfo.Voltage"]', '6554');
    await waitValue(page, 'code.c28x.vars.m_Ulong.value', 122880);
    await page.click('button.code-share');
    const link = await page.evaluate(() => document.documentElement.dataset.codeLink);
    assert(link && link.includes('code=') && link.includes('set.gMotorInfo.Voltage=6554'), link);
    const p2 = await newPage();
    await p2.goto(link.replace('?', '?embed=code&'));
    await p2.waitForSelector('[data-key="code.c28x.vars.m_Ulong.value"][data-value]', { timeout: 60_000 });
    await waitValue(p2, 'code.c28x.vars.m_Ulong.value', 122880, 0, 30_000);
    await waitValue(p2, 'code.arm.vars.m_Ulong.value', 7, 0, 30_000);
    assert((await p2.$$('section.panel')).length === 1, 'embed shows one panel');
    await p2.screenshot({ path: join(SHOTS, 'code-embed.png') });
    await p2.context().close();
  });

  for (const [width, locale] of [[390, 'zh-CN'], [900, 'en-US'], [1366, 'zh-CN']]) {
    await check(`code: screenshot ${width}px ${locale}`, async () => {
      const p = await newPage({ locale, context: { viewport: { width, height: 900 } } });
      await p.goto(`${subSrv.url}?code=${encodeURIComponent(CODE)}&target=c28x&vs=arm&set.gMotorInfo.Voltage=6554`);
      await p.click('nav.tabs a[data-view="firmware"]'); // the code panel's tab
      await p.waitForSelector('[data-key="code.arm.vars.m_Ulong.value"][data-value]', { timeout: 60_000 });
      await p.$eval('#panel-code', (e) => e.scrollIntoView());
      await p.screenshot({ path: join(SHOTS, `code-${width}-${locale}.png`) });
      const overflow = await p.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
      assert(overflow <= 1, `page wider than the viewport by ${overflow}px`);
      await p.context().close();
    });
  }
  await page.context().close();
}
