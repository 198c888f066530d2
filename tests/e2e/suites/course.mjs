// The course (course.html) and its exercises: right and wrong answers set data-exercise-state
// (contract: data-exercise="ID", name="exercise.ID"), a wrong answer shows the hint, a bad one
// a message at the field; a trainee link carries its own motor; progress is kept and exported;
// the trainer page makes links; exercises work in the calculator's explainer (?embed=docs) too.
// The expected answers come from CPython's pulab (tests/oracle/course_oracle.py checks those
// against an oracle without pulab). Screenshots: tests/e2e/screenshots/course-*.png.
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';

export default async function course(ctx) {
  const { check, assert, newPage, subSrv, ROOT, SHOTS } = ctx;
  const py = (code) => JSON.parse(execFileSync('python3', ['-c', `import json; from pulab.analyses import exercises as x; print(json.dumps(${code}))`], {
    cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') },
  }).toString());
  const seed = py('x.trainee_input(0)');
  const seedAnswers = py('{k: v["expected"] for k, v in x.answers(x.trainee_input(0)).items()}');
  const t3 = py('x.trainee_input(3)');
  const t3Answers = py('{k: v["expected"] for k, v in x.answers(x.trainee_input(3)).items()}');
  const hash = (inp) => `#in=${encodeURIComponent(JSON.stringify(inp))}`;
  const courseReady = (page) => page.waitForSelector('html[data-course-ready="ready"]', { timeout: 90_000 });
  const state = (page, id) => page.waitForFunction((i) => document.querySelector(`[data-exercise="${i}"]`)?.getAttribute('data-exercise-state'), id, { timeout: 20_000 }).then((h) => h.jsonValue());
  async function answer(page, id, value) {
    const field = `[name="exercise.${id}"]`;
    await page.evaluate((i) => document.querySelector(`[data-exercise="${i}"]`).removeAttribute('data-exercise-state'), id);
    if (await page.$eval(field, (e) => e.tagName === 'SELECT')) await page.selectOption(field, String(value));
    else await page.fill(field, String(value));
    await page.click(`[data-exercise="${id}"] .ex-form button[type=submit]`);
    return state(page, id);
  }

  const page = await newPage();
  await check('course: the warm-up opens with the seed motor, answers right and wrong set data-exercise-state', async () => {
    await page.goto(`${subSrv.url}course.html?lang=en`);
    await courseReady(page);
    const ids = await page.$$eval('[data-exercise]', (els) => els.map((e) => e.dataset.exercise));
    assert(ids.length >= 5, `warm-up has ${ids.length} exercises`);
    assert(await answer(page, 'warmup-ub', seedAnswers['warmup-ub'].toPrecision(5)) === 'correct', 'U_b right → correct');
    assert(await answer(page, 'warmup-ub', '17') === 'wrong', 'the line voltage → wrong');
    assert(!(await page.$eval('[data-exercise="warmup-ub"] .ex-hint', (e) => e.hidden)), 'hint shown after a wrong answer');
    const solution = await page.$eval('[data-exercise="warmup-ub"] details.ex-solution', (e) => e.open);
    assert(!solution, 'the solution stays closed until asked');
    await page.click('[data-exercise="warmup-ub"] details.ex-solution summary');
    assert(await page.$eval('[data-exercise="warmup-ub"] details.ex-solution', (e) => e.open), 'solution on request');
    await page.fill('[name="exercise.warmup-zb"]', 'abc');
    await page.click('[data-exercise="warmup-zb"] .ex-form button[type=submit]');
    await page.waitForSelector('[name="exercise.warmup-zb"][aria-invalid="true"]', { timeout: 10_000 });
    const msg = await page.$eval('[data-exercise="warmup-zb"] .ex-feedback', (e) => e.textContent);
    assert(/number/.test(msg), `message at the field: ${msg}`);
  });

  await check('course: integer, tracer and prediction exercises in later chapters (±1 stated for pm_kp)', async () => {
    await page.click('[data-course-chapter="01-per-unit"]');
    await page.waitForSelector('[data-exercise="vendor-rpm"]');
    assert(await answer(page, 'vendor-rpm', seedAnswers['vendor-rpm']) === 'correct', 'Rpm');
    assert(await answer(page, 'vendor-rpm', seedAnswers['vendor-rpm'] + 1) === 'wrong', 'Rpm + 1 is wrong (exact)');
    await page.click('[data-exercise="vendor-bug"] [data-ex-trace]');
    await page.waitForSelector('[data-exercise="vendor-bug"] .ex-trace li.flagged', { timeout: 20_000 });
    assert(await answer(page, 'vendor-bug', seedAnswers['vendor-bug']) === 'correct', 'the buggy Rpm from the tracer');
    await page.click('[data-course-chapter="02-current-pi"]');
    await page.waitForSelector('[data-exercise="pi-pm-kp"]');
    assert(await answer(page, 'pi-pm-kp', seedAnswers['pi-pm-kp'] + 1) === 'correct', 'pm_kp + 1 within ±1');
    assert(await answer(page, 'pi-line-trap', seedAnswers['pi-line-trap']) === 'correct', 'the line-voltage trap');
    // choose a base: the seed motor needs more than the firmware's limit already at f_n, so 0
    assert(seedAnswers['pi-choose-fb'] === 0, `seed pi-choose-fb ${seedAnswers['pi-choose-fb']}`);
    assert(await answer(page, 'pi-choose-fb', '220') === 'wrong', 'f_b = f_n keeps the voltage finding');
    assert(await answer(page, 'pi-choose-fb', '0') === 'correct', 'none possible → 0');
    await page.click('[data-course-chapter="03-pll"]');
    await page.waitForSelector('[data-exercise="pll-naive-locks"]');
    assert(seedAnswers['pll-naive-locks'] === 'no', 'the seed motor\'s naive PLL does not lock (19.5 > 2)');
    assert(await answer(page, 'pll-naive-locks', 'yes') === 'wrong', 'predicting a lock is wrong');
    assert(await answer(page, 'pll-naive-locks', 'no') === 'correct', 'no lock → correct');
  });

  await check('course: progress is kept per motor and survives a reload', async () => {
    const saved = await page.evaluate(() => JSON.parse(localStorage.getItem('pulab-course-progress')));
    const motors = Object.values(saved.motors);
    assert(motors.length === 1 && motors[0].exercises['pll-naive-locks'].state === 'correct' && motors[0].exercises['vendor-rpm'].state === 'wrong', JSON.stringify(saved).slice(0, 200));
    await page.reload();
    await courseReady(page);
    assert(await state(page, 'pll-naive-locks') === 'correct', 'state restored after reload');
    const text = await page.$eval('.course-progress', (e) => e.textContent);
    assert(/^\d+ of \d+/.test(text) && !text.startsWith('0 '), text);
    const [dl] = await Promise.all([page.waitForEvent('download'), page.click('[data-course-export]')]);
    assert(dl.suggestedFilename() === 'pulab-course-progress.json', dl.suggestedFilename());
  });

  await check('course: a trainee link carries its own motor; its answers are that motor\'s', async () => {
    const p = await newPage();
    await p.goto(`${subSrv.url}course.html?trainee=3&lang=zh&chapter=01-per-unit${hash(t3)}`);
    await courseReady(p);
    assert(t3Answers['vendor-rpm'] !== seedAnswers['vendor-rpm'], 'trainee 3 has another motor');
    assert(await answer(p, 'vendor-rpm', seedAnswers['vendor-rpm']) === 'wrong', 'the seed\'s Rpm is wrong for trainee 3');
    assert(await answer(p, 'vendor-rpm', t3Answers['vendor-rpm']) === 'correct', 'trainee 3\'s Rpm');
    await p.click('[data-course-chapter="02-current-pi"]');
    await p.waitForSelector('[data-exercise="pi-choose-fb"]');
    const top = t3Answers['pi-choose-fb'];
    assert(top > t3.motor.rated_freq_hz, `trainee 3 can choose an f_b: ${top}`);
    assert(await answer(p, 'pi-choose-fb', (top * 0.999).toFixed(3)) === 'correct', 'an f_b just below the largest: the review rerun has no voltage finding');
    assert(await answer(p, 'pi-choose-fb', (top * 1.05).toFixed(3)) === 'wrong', 'above it: the finding is back');
    assert((await p.$eval('.course-motor', (e) => e.textContent)).includes('学员 3'), 'the header names the trainee');
    await p.context().close();
  });

  await check('course: the trainer page makes trainee links and an answer sheet', async () => {
    const p = await newPage();
    await p.goto(`${subSrv.url}course.html?trainer&first=1&count=3&lang=en`);
    await p.waitForSelector('html[data-trainer-ready="3"]', { timeout: 90_000 });
    const links = await p.$$eval('[data-trainee-link]', (els) => els.map((e) => e.getAttribute('href')));
    assert(links.length === 3 && links.every((l) => l.includes('#in=') && l.includes('course.html?trainee=')), links.join(' '));
    const rows = await p.$$eval('.trainer-sheet tbody tr', (r) => r.length);
    assert(rows === Object.keys(seedAnswers).length, `answer sheet rows ${rows}`);
    await p.context().close();
  });

  await check('explainer: exercises work in ?embed=docs&chapter=00-warm-up of the calculator', async () => {
    const p = await newPage();
    await p.goto(`${subSrv.url}?embed=docs&chapter=00-warm-up${hash(seed)}`);
    await p.waitForSelector('[data-exercise="warmup-rs"] [name="exercise.warmup-rs"]', { timeout: 90_000 });
    await p.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 90_000 });
    assert(await answer(p, 'warmup-rs', seedAnswers['warmup-rs'].toPrecision(4)) === 'correct', 'R_s* right');
    assert(await answer(p, 'warmup-rs', '1.5') === 'wrong', 'R_s in ohms is wrong');
    await p.context().close();
  });

  await check('course: the answer key (print=key) lists every exercise with the engine\'s answer and opens the solutions', async () => {
    const p = await newPage();
    await p.goto(`${subSrv.url}course.html?print=key&lang=en`);
    await courseReady(p);
    const rows = await p.$$eval('.course-key-table tbody tr', (r) => r.map((x) => [x.children[1].textContent, x.children[2].textContent]));
    assert(rows.length === Object.keys(seedAnswers).length, `${rows.length} rows`);
    const rpm = rows.find(([id]) => id === 'vendor-rpm');
    assert(rpm && rpm[1].trim() === String(seedAnswers['vendor-rpm']), JSON.stringify(rpm));
    const closed = await p.$$eval('details.ex-solution:not([open])', (d) => d.length);
    assert(closed === 0, `${closed} solutions closed in the key`);
    await p.context().close();
  });

  await check('course: screenshots 390/900/1366 px, zh and en, and the handout layouts', async () => {
    const p = await newPage();
    for (const lang of ['zh', 'en']) {
      for (const w of [390, 900, 1366]) {
        await p.setViewportSize({ width: w, height: 900 });
        await p.goto(`${subSrv.url}course.html?lang=${lang}&chapter=02-current-pi`);
        await courseReady(p);
        await p.screenshot({ path: join(SHOTS, `course-${lang}-${w}.png`) });
        // the calculator's header with its Course link
        await p.goto(`${subSrv.url}?lang=${lang}`);
        await p.waitForSelector('header.top a[data-course-link]');
        await (await p.$('header.top')).screenshot({ path: join(SHOTS, `course-link-${lang}-${w}.png`) });
      }
    }
    await p.click('header.top a[data-course-link]');
    await courseReady(p);
    assert(p.url().includes('course.html') && p.url().includes('#in='), `the Course link carries the motor: ${p.url()}`);
    await p.context().close();
  });
  await page.context().close();
}
