// Every screen: the first screen shows the answer (the shipped firmware's integers, the review
// summary) at 390/900/1366 px in en and zh, the inputs one tap away; a profile picker; every panel
// reachable through the views; wide content says it scrolls; the Export menu closes as menus do;
// data-numbers and the stale note while typing; sweep boundaries as typed decimals; one inductance
// unit; a datasheet conflict marks both fields; a blank datasheet start.
// Run alone: node tests/e2e/run.mjs screens   (E2E_NO_BUILD=1 to reuse dist/)
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

const WIDTHS = [[390, 844], [900, 900], [1366, 768]];

export default async function screens(ctx) {
  const { check, assert, newPage, subSrv, ready, waitValue, cpython, golden, ROOT, SHOTS } = ctx;
  const seed = golden('01_seed_motor.json');
  const link = (inp) => `${subSrv.url}#in=${encodeURIComponent(JSON.stringify(inp))}`;
  /** The rectangle of the first element matching `sel` (null when absent or not rendered). */
  const rect = (p, sel) => p.$eval(sel, (e) => {
    const r = e.getBoundingClientRect();
    return r.width && r.height ? { top: r.top, bottom: r.bottom, left: r.left, right: r.right } : null;
  }).catch(() => null);
  const numbers = (p) => p.evaluate(() => document.documentElement.dataset.numbers);

  for (const lang of ['en', 'zh']) {
    for (const [w, hgt] of WIDTHS) {
      await check(`screens: ${w} px (${lang}): the first screen shows the integers and the review; inputs one tap away`, async () => {
        const p = await newPage({ context: { viewport: { width: w, height: hgt } } });
        await p.goto(`${subSrv.url}?lang=${lang}`);
        await ready(p);
        await p.waitForSelector('section.answer [data-key="vendor.Rpm.value"][data-value]');
        const inView = async (sel) => {
          const r = await rect(p, sel);
          return r !== null && r.top >= 0 && r.bottom <= hgt && r.left >= 0 && r.right <= w;
        };
        for (const k of ['vendor.Rpm.value', 'vendor.LD.value', 'vendor.maxu.value', 'current_pi.d.pm_ki']) {
          assert(await inView(`section.answer [data-key="${k}"]`), `${k} not on the first screen`);
          assert(await p.$eval(`section.answer [data-key="${k}"]`, (e) => JSON.parse(e.dataset.value)) === seed.expected[k.split('.')[0]][k.split('.')[1]][k.split('.')[2]], `${k} value`);
        }
        assert(await inView('section.answer .counts'), 'review summary not on the first screen');
        // The strip is patched again when the live report replaces the build's numbers, and a
        // select is replaced, not patched: give the layout up to 3 s to settle, then say where it was.
        let seen = await inView('select[name="answer.profile"]');
        for (let k = 0; !seen && k < 30; k++) {
          await p.waitForTimeout(100);
          seen = await inView('select[name="answer.profile"]');
        }
        assert(seen, `profile picker not on the first screen: ${JSON.stringify(await rect(p, 'select[name="answer.profile"]'))}, scrollY ${await p.evaluate(() => window.scrollY)}`);
        const tabs = await p.$$eval('nav.tabs a[data-view]', (as) => as.map((a) => a.getBoundingClientRect().right));
        assert(tabs.every((r) => r <= w), `a tab off screen: ${tabs.map(Math.round)} at ${w}`);
        const doc = await p.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.scrollHeight]);
        assert(doc[0] <= w, `page ${doc[0]} px wide at ${w}`);
        await p.screenshot({ path: join(SHOTS, `screens-${w}-${lang}-first.png`) });
        if (w < 1000) {
          assert(!(await p.isVisible('input[name="motor.rs_ohm"]')), 'inputs shown over the answer on a narrow screen');
          assert(await inView('nav.tabs .inputs-toggle'), 'no inputs button on the first screen');
          await p.click('nav.tabs .inputs-toggle');
          await p.waitForSelector('input[name="motor.rs_ohm"]', { state: 'visible' });
          await p.waitForTimeout(250); // the drawer slides in
          assert(await inView('input[name="motor.rated_voltage_v"]'), 'first input not on screen after one tap');
          await p.screenshot({ path: join(SHOTS, `screens-${w}-${lang}-inputs.png`) });
          await p.keyboard.press('Escape');
          await p.waitForSelector('input[name="motor.rs_ohm"]', { state: 'hidden' });
        } else {
          assert(await inView('input[name="motor.rated_voltage_v"]'), 'inputs not beside the answer');
        }
        // every view's panels are reachable through its tab
        for (const tab of await p.$$eval('nav.tabs a[data-view]', (as) => as.map((a) => a.dataset.view))) {
          await p.click(`nav.tabs a[data-view="${tab}"]`);
          const shown = await p.$$eval('section.panel:not([hidden])', (s) => s.map((e) => e.dataset.panel));
          assert(shown.length > 0, `view ${tab} shows no panel`);
          assert(await p.$eval(`nav.tabs a[data-view="${tab}"]`, (a) => a.classList.contains('on')), `tab ${tab} not marked`);
        }
        const all = await p.$$eval('section.panel', (s) => s.map((e) => e.dataset.panel));
        const reached = new Set();
        for (const tab of await p.$$eval('nav.tabs a[data-view]', (as) => as.map((a) => a.dataset.view))) {
          await p.click(`nav.tabs a[data-view="${tab}"]`);
          for (const id of await p.$$eval('section.panel:not([hidden])', (s) => s.map((e) => e.dataset.panel))) reached.add(id);
        }
        assert(all.every((id) => reached.has(id)), `unreachable: ${all.filter((id) => !reached.has(id))}`);
        // wide content at a phone width: the vendor table scrolls inside its panel and says so
        if (w === 390) {
          await p.click('nav.tabs a[data-view="design"]');
          await p.$eval('#panel-vendor', (e) => e.scrollIntoView());
          await p.waitForSelector('#panel-vendor.x-scroll h2 .scroll-cue', { state: 'visible', timeout: 5000 });
          await p.screenshot({ path: join(SHOTS, `screens-${w}-${lang}-scroll-cue.png`) });
        }
        await p.context().close();
      });
    }
  }

  await check('screens: the profile picker shows each firmware\'s integers (equal CPython); one that cannot hold the motor says why', async () => {
    const robot = golden('23_limit_robot_28krpm.json');
    const want = cpython({ ...robot.input, profiles: {} });
    // The strip counts the review of the firmware picked and, once the simulation (the page's
    // default "sim" section) has answered, the simulation's own findings (key "sim."): CPython's
    // report of each, without and with that section.
    const FW = ['ti', 'nxp', 'st', 'microchip'];
    const SIM = { current: { axis: 'd', delay: false }, pll: {} };
    const graded = (fw, sim) => ({ ...robot.input, conventions: { ...robot.input.conventions, firmware: fw }, ...(sim ? { sim: SIM } : {}) });
    const reports = JSON.parse(execFileSync('python3', ['-c', 'import json,sys; from pulab import report; print(json.dumps([{"review": report(i)["review"]} for i in json.load(sys.stdin)]))'], {
      cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: JSON.stringify(FW.flatMap((fw) => [graded(fw, false), graded(fw, true)])),
    }).toString());
    const countsText = (findings) => {
      const n = (s) => findings.filter((f) => f.severity === s).length;
      return `${n('error')} errors, ${n('warning')} warnings, ${n('note')} notes`;
    };
    const strip = Object.fromEntries(FW.map((fw, k) => {
      const [plain, simmed] = [reports[2 * k], reports[2 * k + 1]];
      const sims = simmed.review.findings.filter((f) => f.key.startsWith('sim.'));
      return [fw, [countsText(plain.review.findings), countsText([...plain.review.findings, ...sims])]];
    }));
    const p = await newPage({ context: { viewport: { width: 390, height: 844 } } });
    await p.goto(link(robot.input));
    await ready(p);
    await p.waitForSelector('section.answer .firmware-limits [data-field="raw.FullFreq01"]', { timeout: 30_000 });
    assert(await p.isVisible('section.answer .firmware-limits'), 'Inovance limits not shown in the answer');
    await p.screenshot({ path: join(SHOTS, 'screens-profile-inovance-limit.png') });
    for (const v of FW) {
      await p.selectOption('select[name="answer.profile"]', v);
      const names = Object.keys(want.profiles[v].constants);
      const sel = `section.answer [data-key="profiles.${v}.constants.${names[0]}.value"][data-value]`;
      await p.waitForSelector(sel, { timeout: 30_000 });
      const shown = await p.$$eval('section.answer [data-key][data-value]', (els) => els.map((e) => [e.dataset.key, JSON.parse(e.dataset.value)]));
      const bad = shown.filter(([k, x]) => {
        const [, , , name] = k.split('.');
        return want.profiles[v].constants[name]?.value !== x;
      });
      assert(shown.length === names.length && bad.length === 0, `${v}: ${shown.length} of ${names.length} shown, differing ${bad}`);
      const limited = !want.firmware[v].representable;
      assert((await p.$('section.answer .firmware-limits')) !== null === limited, `${v}: limits box ${limited ? 'missing' : 'shown'}`);
      // the pick is the input's conventions.firmware: the form follows, the review grades by it
      assert((await p.inputValue('select[name="conventions.firmware"]')) === v, `${v}: form field`);
      await p.waitForFunction((texts) => texts.some((c) => (document.querySelector('section.answer .counts')?.textContent ?? '').includes(c)), strip[v], { timeout: 10_000 });
    }
    // once any simulation has answered, the strip counts its findings
    const { done, text } = await p.evaluate(() => ({ done: Number(document.documentElement.dataset.simDone ?? 0), text: document.querySelector('section.answer .counts')?.textContent ?? '' }));
    assert(text.includes(strip.microchip[done > 0 ? 1 : 0]), `strip "${text}" with ${done} simulations answered`);
    await p.screenshot({ path: join(SHOTS, 'screens-profile-microchip.png') });
    // the choice is remembered
    await p.reload();
    await ready(p);
    assert((await p.inputValue('select[name="answer.profile"]')) === 'microchip', 'profile not remembered');
    await p.selectOption('select[name="answer.profile"]', 'inovance');
    await p.context().close();
  });

  const page = await newPage();
  await check('screens: the Export menu closes on an item, a click outside and Esc', async () => {
    await page.goto(subSrv.url);
    await ready(page);
    const open = () => page.$eval('details.export', (d) => d.open);
    await page.click('.export > summary');
    assert(await open(), 'menu did not open');
    await page.mouse.click(700, 600);
    assert(!(await open()), 'still open after a click outside');
    await page.click('.export > summary');
    await page.keyboard.press('Escape');
    assert(!(await open()), 'still open after Esc');
    await page.click('.export > summary');
    const [dl] = await Promise.all([page.waitForEvent('download'), page.click('button[data-export="json"]')]);
    assert(dl.suggestedFilename().endsWith('.json'), 'no download');
    assert(!(await open()), 'still open after choosing an item');
  });

  await check('screens: "abc" in a field → data-numbers stale, the reason beside the inputs while typing; fixed → live', async () => {
    await page.fill('input[name="motor.rs_ohm"]', 'abc');
    await page.waitForFunction(() => document.documentElement.dataset.numbers === 'stale', null, { timeout: 5000 });
    const note = await rect(page, 'aside.inputs .stale-note');
    assert(note && note.top >= 0 && note.bottom <= 768, 'stale note not on screen at 1366');
    assert((await page.textContent('aside.inputs .stale-note')).includes('motor.rs_ohm'), 'stale note without the field');
    await page.fill('input[name="motor.rs_ohm"]', '1.5');
    await page.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 10_000 });
    assert((await page.textContent('aside.inputs .stale-note')) === '', 'stale note left behind');
    // on a phone, in the drawer, scrolled down to a field far below
    await page.setViewportSize({ width: 390, height: 844 });
    await page.click('nav.tabs .inputs-toggle');
    await page.fill('input[name="drive.ts_s"]', 'x');
    await page.waitForFunction(() => document.documentElement.dataset.numbers === 'stale');
    const n2 = await rect(page, 'aside.inputs .stale-note');
    assert(n2 && n2.top >= 0 && n2.bottom <= 844, 'stale note off screen while editing in the drawer');
    await page.screenshot({ path: join(SHOTS, 'screens-390-stale-drawer.png') });
    await page.fill('input[name="drive.ts_s"]', '100');
    await page.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 10_000 });
    await page.keyboard.press('Escape');
    await page.setViewportSize({ width: 1366, height: 768 });
  });

  await check('screens: one inductance unit for the motor and the datasheet fields', async () => {
    await page.$eval('details[data-section="datasheet"]', (d) => { d.open = true; });
    const units = () => page.$$eval('select.unit', (s) => s.filter((e) => /_h$/.test(e.dataset.unitFor)).map((e) => e.value));
    const u0 = await units();
    assert(u0.length >= 5 && u0.every((u) => u === 'µH'), `units ${u0}`);
    await page.selectOption('select[data-unit-for="datasheet.l_line_h"]', 'mH');
    const u1 = await units();
    assert(u1.every((u) => u === 'mH'), `after choosing mH: ${u1}`);
    assert((await page.inputValue('input[name="motor.ld_h"]')) === '0.6', 'Ld not shown in mH');
    await page.selectOption('select[data-unit-for="motor.ld_h"]', 'µH');
    assert((await units()).every((u) => u === 'µH'), 'back to µH');
  });

  await check('screens: a datasheet conflict marks both fields with one full sentence', async () => {
    await page.fill('input[name="datasheet.speed_rpm"]', '3000');
    await page.waitForSelector('.field.invalid [data-err-for="motor.rated_freq_hz"]', { timeout: 10_000 });
    const a = await page.textContent('[data-err-for="datasheet.speed_rpm"]');
    const b = await page.textContent('[data-err-for="motor.rated_freq_hz"]');
    assert(a === b && /^[A-Z].*both set .*: give only one of them\.$/.test(a), `messages: "${a}" / "${b}"`);
    assert(await page.$eval('[data-err-for="datasheet.speed_rpm"]', (e) => e.closest('.field').classList.contains('invalid')), 'datasheet field not marked');
    await page.$eval('[data-err-for="motor.rated_freq_hz"]', (e) => e.scrollIntoView({ block: 'center' }));
    await page.screenshot({ path: join(SHOTS, 'screens-conflict.png') });
    await page.fill('input[name="datasheet.speed_rpm"]', '');
    await page.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 10_000 });
  });

  await check('screens: "Start from a datasheet" leaves nothing of the example motor', async () => {
    await page.click('button.from-datasheet');
    await page.waitForFunction(() => document.documentElement.dataset.numbers === 'stale');
    // The simulation and analysis defaults every new input gets (as a share link does) are not the motor's.
    const left = await page.$$eval('aside.inputs input[type="text"]', (els) => els.filter((e) => e.value !== '' && !/^(sim|analysis)\./.test(e.name)).map((e) => `${e.name}=${e.value}`));
    assert(left.length === 0, `seed values left: ${left.join(', ')}`);
    const hints = await page.$$eval('aside.inputs input[type="text"]', (els) => els.filter((e) => e.placeholder !== '').map((e) => `${e.name} ${e.placeholder}`));
    assert(hints.length === 0, `placeholders of the example motor: ${hints.join(', ')}`);
    assert(await page.$eval('details[data-section="datasheet"]', (d) => d.open), 'datasheet section not open');
    assert(await page.isVisible('aside.inputs .blank-start'), 'no note that the form is blank');
    assert(!(await page.evaluate(() => location.hash.includes('rated_voltage_v'))), 'seed still in the link');
    await page.screenshot({ path: join(SHOTS, 'screens-blank-datasheet.png') });
    await page.selectOption('select[name="preset"]', 'seed');
    await waitValue(page, 'vendor.Rpm.value', 15022);
  });

  // Six real motors (tests/golden/datasheets, hand calculations by a pulab-free oracle): typed into
  // a blank form as the datasheet prints them, inductances in the datasheet's unit, Ts in µs.
  const DATASHEETS = ['siemens_1ft7044_ak7', 'rexroth_mhd041a_144', 'rexroth_mhp112a_024', 'maxon_ec45flat_50w_24v', 'maxon_ec45flat_70w_411812', 'emrax_228_lv'];
  // EMRAX prints µH and a Ke in "Vrms/1RPM": the form's unit choices take them as printed.
  const PRINTED_UNITS = { emrax_228_lv: { L: 'µH', 'datasheet.ke_v_per_krpm': 'V/rpm' } };
  const SCALE = { 'µH': 1e6, mH: 1e3, 'V/rpm': 1e-3 };
  const typed = (path, v, units) => {
    const unit = /_h$/.test(path) ? units.L : units[path];
    return String(Number((unit ? v * SCALE[unit] : path === 'drive.ts_s' ? v * 1e6 : v).toPrecision(12)));
  };
  const flat = (o, p = '', out = []) => {
    if (o && typeof o === 'object' && !Array.isArray(o)) for (const [k, v] of Object.entries(o)) flat(v, p ? `${p}.${k}` : k, out);
    else if (typeof o === 'number') out.push([p, o]);
    return out;
  };
  const same = (a, e) => (Number.isInteger(e) ? a === e : Math.abs(a - e) <= 1e-9 * Math.max(Math.abs(a), Math.abs(e)));
  for (const name of DATASHEETS) {
    await check(`screens: ${name} typed from a blank datasheet gives the hand calculation, every firmware's integers or its limits`, async () => {
      const g = JSON.parse(readFileSync(join(ROOT, `tests/golden/datasheets/${name}.json`), 'utf8'));
      await page.click('button.from-datasheet');
      const units = { L: 'mH', ...PRINTED_UNITS[name] };
      for (const [path, unit] of Object.entries(units)) {
        await page.selectOption(`select[data-unit-for="${path === 'L' ? 'datasheet.l_line_h' : path}"]`, unit);
      }
      for (const [section, fields] of Object.entries(g.input)) {
        for (const [k, v] of Object.entries(fields)) {
          const path = `${section}.${k}`;
          if (typeof v === 'string') await page.selectOption(`select[name="${path}"]`, v);
          else await page.fill(`input[name="${path}"]`, typed(path, v, units));
        }
      }
      await page.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 15_000 });
      const shown = new Map(await page.$$eval('[data-key][data-value]', (els) => els.map((e) => [e.dataset.key, JSON.parse(e.dataset.value)])));
      const want = flat(Object.fromEntries(Object.entries(g.expected).filter(([k]) => !['profiles', 'firmware.inovance'].includes(k))));
      const hits = want.filter(([k]) => shown.has(k));
      const bad = hits.filter(([k, e]) => !same(shown.get(k), e)).map(([k, e]) => `${k}: page ${shown.get(k)}, by hand ${e}`);
      assert(hits.length >= 40 && bad.length === 0, `${hits.length} compared; ${bad.slice(0, 5).join('; ')}`);
      // Inovance: the problems by hand, or its integers
      const limits = await page.$$eval('section.answer .firmware-limits [data-field]', (els) => els.map((e) => e.dataset.field));
      assert(JSON.stringify(limits) === JSON.stringify(g.expected['firmware.inovance'].problems.map((x) => x.field)), `Inovance limits ${limits}`);
      for (const [v, consts] of Object.entries(g.expected.profiles)) {
        await page.selectOption('select[name="answer.profile"]', v);
        const first = Object.keys(consts)[0];
        await page.waitForFunction(([p, x]) => {
          const e = document.querySelector(`section.answer [data-key="${p}"][data-value]`);
          return e && JSON.parse(e.dataset.value) === x;
        }, [`profiles.${v}.constants.${first}.value`, consts[first].value], { timeout: 15_000 });
        const chips = new Map(await page.$$eval('section.answer [data-key][data-value]', (els) => els.map((e) => [e.dataset.key, JSON.parse(e.dataset.value)])));
        const off = Object.entries(consts).filter(([k, c]) => chips.get(`profiles.${v}.constants.${k}.value`) !== c.value);
        assert(off.length === 0, `${v}: ${off.map(([k, c]) => `${k} page ${chips.get(`profiles.${v}.constants.${k}.value`)} by hand ${c.value}`).join(', ')}`);
      }
      await page.selectOption('select[name="answer.profile"]', 'inovance');
      await page.screenshot({ path: join(SHOTS, `screens-datasheet-${name}.png`) });
      console.log(`      ${hits.length} numbers and ${Object.keys(g.expected.profiles).length} firmware equal the hand calculation`);
    });
  }
  await page.selectOption('select[data-unit-for="motor.ld_h"]', 'µH');
  await page.selectOption('select[data-unit-for="datasheet.ke_v_per_krpm"]', 'V/krpm');

  await check('screens: sweep boundaries print the decimal a user would type, the exact double in data-value', async () => {
    await page.$eval('#panel-sweep', (e) => e.scrollIntoView());
    await page.selectOption('select[name="sweep.x.path"]', 'motor.rated_current_a');
    await page.fill('input[name="sweep.x.start"]', '1');
    await page.fill('input[name="sweep.x.stop"]', '200');
    await page.fill('input[name="sweep.x.n"]', '400');
    await page.selectOption('select[name="sweep.x.scale"]', 'linear');
    await page.click('button.run-sweep');
    await page.waitForFunction(() => document.documentElement.dataset.sweepDone === '400', null, { timeout: 60_000 });
    const rows = await page.$$eval('table.sweep-bounds [data-key$=".at"]', (els) => els.map((e) => [e.textContent, JSON.parse(e.dataset.value)]));
    const hit = rows.find(([, v]) => v === 125.05499999999999);
    assert(hit && hit[0] === '125.055', `boundary shown as ${hit?.[0]}`);
    assert(rows.every(([text, v]) => Number(text) >= v && Math.abs(Number(text) - v) <= 1e-9 * Math.abs(v)), JSON.stringify(rows));
  });
  await page.context().close();
}
