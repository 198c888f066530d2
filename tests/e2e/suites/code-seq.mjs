// "Over many calls" in the Code view: the chosen function called N times with generated
// per-call inputs (the CLI's --gen spec), each call's result equal to the CLI's, the first
// wrap and the generator's clamps said; a bad spec names its input. Screenshots in zh and en.
// Run alone: node tests/e2e/run.mjs code-seq   (E2E_NO_BUILD=1 to reuse dist/)
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';

const CODE = `#include <stdint.h>
int16_t acc;
int16_t f(int16_t e) { acc += e; return acc; }
`;

export default async function codeSeq(ctx) {
  const { check, assert, newPage, ready, subSrv, ROOT, SHOTS } = ctx;
  const cli = (calls, gen) => JSON.parse(execFileSync('python3',
    ['-m', 'pulab', 'trace', '-', '--target', 'arm', '--entry', 'f', '--set', 'acc=0', '--calls', String(calls), '--gen', gen],
    { cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: CODE }).toString());
  const url = `${subSrv.url}?code=${encodeURIComponent(CODE)}&target=arm&vs=&entry=f&set.acc=0`;
  const p = await newPage({ context: { viewport: { width: 1366, height: 900 } } });
  const run = async (calls, gen) => {
    await p.fill('#panel-code input[name="calls"]', String(calls));
    await p.fill('#panel-code input[name="gen"]', gen);
    await p.click('#panel-code .code-seq-run');
  };

  await check('code seq: generated inputs over N calls equal the CLI call by call, first wrap and clamps said', async () => {
    await p.goto(url);
    await ready(p);
    await p.click('nav.tabs a[data-view="firmware"]');
    await p.waitForSelector('#panel-code .code-seq-run', { timeout: 60_000 });
    // the single trace's reply first: it names the inputs (acc, e) whose values the calls start from
    await p.waitForSelector('#panel-code input[name="set.e"]', { state: 'attached', timeout: 60_000 });
    await run(40, 'e=ramp:start=0,slope=1000');
    await p.waitForSelector('[data-key="code.seq.calls.39.return.value"][data-value]', { state: 'attached', timeout: 60_000 });
    const want = cli(40, 'e=ramp:start=0,slope=1000');
    const shown = await p.$$eval('[data-key^="code.seq.calls."][data-value]', (els) => els.map((e) => Number(e.dataset.value)));
    const expect = want.calls.map((c) => c.return.value);
    assert(JSON.stringify(shown) === JSON.stringify(expect), `returns ${shown.slice(0, 12)} vs CLI ${expect.slice(0, 12)}`);
    const event = await p.$eval('[data-key="code.seq.first_event"]', (e) => JSON.parse(e.dataset.value));
    assert(JSON.stringify(event) === JSON.stringify(want.first_event) && event.call === 8, `first event ${JSON.stringify(event)}`);
    await run(8, 'e=sine:amp=40000,period=4');
    await p.waitForFunction(() => document.querySelectorAll('[data-key^="code.seq.calls."][data-value]').length === 8, null, { timeout: 60_000 });
    const clamped = await p.$eval('[data-key="code.seq.generated.e.clamped"]', (e) => Number(e.dataset.value));
    assert(clamped === cli(8, 'e=sine:amp=40000,period=4').generated.e.clamped && clamped === 4, `clamped ${clamped}`);
    await p.$eval('#panel-code .code-seq-plot', (e) => e.scrollIntoView({ block: 'center' }));
    await p.waitForSelector('#panel-code .code-seq-plot .main-svg', { timeout: 30_000 });
    const legend = await p.$$eval('#panel-code .code-seq-plot .legendtext', (els) => els.map((e) => e.textContent));
    assert(legend.includes('e') && legend.length === 2, `legend ${legend}`);
    await p.screenshot({ path: join(SHOTS, 'code-seq-1366-en.png') });
  });

  await check('code seq: a bad generator spec is one line naming the input', async () => {
    await run(10, 'e=sine:amp=1');
    await p.waitForSelector('#panel-code .code-seq-err', { timeout: 60_000 });
    const text = await p.$eval('#panel-code .code-seq-err', (e) => e.textContent);
    assert(text === 'gen.e: sine needs period=…', `error ${text}`);
    assert(!(await p.$('[data-key^="code.seq.calls."]')), 'no calls shown beside the error');
  });

  await check('code seq: the box at 390 px in zh without overflow', async () => {
    await p.setViewportSize({ width: 390, height: 900 });
    await p.click('button[data-lang="zh"]');
    await run(20, 'e=step:at=5,after=300');
    await p.waitForFunction(() => document.querySelectorAll('[data-key^="code.seq.calls."][data-value]').length === 20, null, { timeout: 60_000 });
    const over = await p.$eval('#panel-code', (e) => e.scrollWidth - e.clientWidth);
    assert(over <= 1, `#panel-code overflows by ${over} px`);
    await p.$eval('#panel-code .code-seq-box', (e) => e.scrollIntoView());
    await p.screenshot({ path: join(SHOTS, 'code-seq-390-zh.png') });
  });
  await p.context().close();
}
