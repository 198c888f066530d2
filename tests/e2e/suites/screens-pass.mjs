// The page as a user meets it, past the first screen: a share link opened in a tab that is
// already open, one Python call per keystroke whichever firmware is shipped, and what a new
// user's pass over the five datasheet motors found.
// Run alone: node tests/e2e/run.mjs screens-pass   (E2E_NO_BUILD=1 to reuse dist/)
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

export default async function screensPass(ctx) {
  const { check, assert, newPage, subSrv, ready, waitValue, cpython, golden, ROOT, SHOTS } = ctx;
  const seed = golden('01_seed_motor.json');
  const link = (inp) => `${subSrv.url}#in=${encodeURIComponent(JSON.stringify(inp))}`;

  await check('screens-pass: a share link differing only in its hash, opened in an open tab, sets the inputs, units, view and numbers', async () => {
    const g = golden('04_ind380_7k5.json');
    const p = await newPage({ context: { viewport: { width: 390, height: 844 } } });
    await p.goto(subSrv.url);
    await ready(p);
    await waitValue(p, 'vendor.Rpm.value', seed.expected.vendor.Rpm.value);
    await p.click('nav.tabs a[data-view="loops"]');
    await p.click('nav.tabs .inputs-toggle');
    await p.evaluate(() => { window.sameDocument = true; });
    await p.goto(`${link(g.input)}&u=${encodeURIComponent(JSON.stringify({ 'motor.ld_h': 'mH' }))}`);
    await waitValue(p, 'vendor.Rpm.value', g.expected.vendor.Rpm.value);
    assert(await p.evaluate(() => window.sameDocument === true), 'the page was reloaded: not a hash-only change');
    await p.waitForFunction(() => document.documentElement.dataset.numbers === 'live');
    const view = await p.$eval('nav.tabs a.on', (a) => a.dataset.view);
    assert(view === 'design', `view ${view} kept from before the link`);
    assert(!(await p.$eval('#panel-review', (e) => e.hidden)) && await p.$eval('#panel-loop', (e) => e.hidden), 'panels of the old view shown');
    assert(!(await p.evaluate(() => document.body.classList.contains('inputs-open'))), 'drawer left open over the new answer');
    assert((await p.inputValue('input[name="motor.rated_voltage_v"]')) === '380', 'inputs not from the link');
    const ld = [await p.inputValue('select[data-unit-for="motor.ld_h"]'), await p.inputValue('input[name="motor.ld_h"]')];
    assert(ld.join(' ') === 'mH 8.5', `units not from the link: ${ld}`);
    assert(await p.isVisible('section.answer [data-key="vendor.Rpm.value"]'), 'answer not on screen');
    await p.screenshot({ path: join(SHOTS, 'screens-390-hash-link.png') });
    await p.context().close();
  });

  await check('screens-pass: a link opened while a report rewrites the address bar is still followed', async () => {
    // The race as it happens: the fragment navigation changes the URL, a report answered just
    // before writes its own input back with replaceState, then the hashchange event runs.
    const g = golden('04_ind380_7k5.json');
    const p = await newPage();
    await p.goto(subSrv.url);
    await ready(p);
    await waitValue(p, 'vendor.Rpm.value', seed.expected.vendor.Rpm.value);
    const target = link(g.input);
    await p.evaluate((to) => {
      const old = location.href;
      history.replaceState(history.state, '', old);
      window.dispatchEvent(new HashChangeEvent('hashchange', { oldURL: old, newURL: to }));
    }, target);
    await waitValue(p, 'vendor.Rpm.value', g.expected.vendor.Rpm.value);
    assert((await p.inputValue('input[name="motor.rated_voltage_v"]')) === '380', 'inputs not from the link');
    await p.context().close();
  });

  await check('screens-pass: with a non-Inovance firmware shipped, one report call per keystroke serves the numbers and the answer strip', async () => {
    const g = golden('04_ind380_7k5.json');
    const inp = { ...g.input, conventions: { firmware: 'microchip' } };
    const want = cpython(inp);
    const p = await newPage();
    // Count the page's calls to the Python workers by kind and channel (the SharedWorker's port).
    await p.addInitScript(() => {
      window.pyCalls = [];
      const post = MessagePort.prototype.postMessage;
      MessagePort.prototype.postMessage = function (m, ...rest) {
        if (m && m.type === 'call') window.pyCalls.push(`${m.kind}/${m.channel}`);
        return post.call(this, m, ...rest);
      };
    });
    await p.goto(link(inp));
    await ready(p);
    const key = 'profiles.microchip.constants.KII.value';
    await waitValue(p, key, want.profiles.microchip.constants.KII.value);
    await p.waitForTimeout(1500); // the first simulation and the panels' own calls settle
    await p.evaluate(() => { window.pyCalls.length = 0; });
    await p.fill('input[name="motor.rs_ohm"]', '0.84');
    const after = cpython({ ...inp, motor: { ...inp.motor, rs_ohm: 0.84 } });
    await waitValue(p, key, after.profiles.microchip.constants.KII.value);
    await p.waitForFunction(() => document.documentElement.dataset.numbers === 'live');
    await p.waitForTimeout(300);
    // The simulation's own call (channel "sim", after its pause) may follow on a loaded machine:
    // what is counted is the calls that serve the numbers and the strip.
    const calls = await p.evaluate(() => window.pyCalls.filter((c) => c.startsWith('report/') && c !== 'report/sim'));
    assert(JSON.stringify(calls) === JSON.stringify(['report/report']), `report calls per keystroke: ${calls}`);
    assert(after.profiles.microchip.constants.KII.value !== want.profiles.microchip.constants.KII.value, 'the edit does not move KII: not a test');
    await p.context().close();
  });


  await check('screens-pass: a firmware that cannot hold a datasheet motor says why at its own panel, first in the Firmware view, and in the strip once shipped', async () => {
    // The Rexroth MHP112A-024 as printed: Microchip's MCAF_MOTOR_PSI_BASE_DT needs 1.68× its Q13
    // (the pulab-free oracle's integers, tests/golden/datasheets); Inovance holds it.
    const g = JSON.parse(readFileSync(join(ROOT, 'tests/golden/datasheets/rexroth_mhp112a_024.json'), 'utf8'));
    const want = g.expected.profiles.microchip.MCAF_MOTOR_PSI_BASE_DT;
    assert(want.value === 32767, `oracle: stored ${want.value}`);
    const p = await newPage({ context: { viewport: { width: 390, height: 844 } } });
    await p.goto(`${link(g.input).replace('#', '?lang=zh#')}`);
    await ready(p);
    await p.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 30_000 });
    await p.click('nav.tabs a[data-view="firmware"]');
    const order = await p.$$eval('section.panel:not([hidden])', (s) => s.map((e) => e.dataset.panel));
    const nav = await p.$$eval('nav.subtabs a[data-nav]', (as) => as.map((a) => a.dataset.nav));
    assert(JSON.stringify(order) === JSON.stringify(nav) && order[0] === 'vendors', `Firmware view shows ${order}, its navigation lists ${nav}`);
    const box = '#panel-vendors .firmware-limits[data-firmware="microchip"]';
    await p.waitForSelector(`${box} [data-field="profiles.microchip.MCAF_MOTOR_PSI_BASE_DT"]`, { timeout: 30_000 });
    assert(/Q12/.test(await p.textContent(box)), 'the advice does not name the Q format that holds it');
    const said = await p.$eval(`${box} li`, (li) => [...li.childNodes].filter((n) => !(n instanceof Element && n.classList.contains('hint'))).map((n) => n.textContent).join(''));
    assert(said.split('MCAF_MOTOR_PSI_BASE_DT').length === 2, `the constant named more than once: "${said}"`);
    assert((await p.$$('#panel-vendors .firmware-limits')).length === 1, 'a firmware that holds the motor shows a limits box');
    const lines = await p.$$eval('#panel-vendors > h2 .why, #panel-vendors > h2 .scroll-cue', (els) => els.map((e) => e.getClientRects().length));
    assert(lines.length === 2 && lines.every((n) => n === 1), `"why?" or the scroll cue broken over lines: ${lines}`);
    await p.screenshot({ path: join(SHOTS, 'screens-pass-390-zh-firmware-limits.png') });
    await p.selectOption('select[name="answer.profile"]', 'microchip');
    await waitValue(p, 'profiles.microchip.constants.MCAF_MOTOR_PSI_BASE_DT.value', want.value);
    await p.waitForSelector('section.answer .firmware-limits[data-firmware="microchip"] [data-field="profiles.microchip.MCAF_MOTOR_PSI_BASE_DT"]', { timeout: 10_000 });
    await p.context().close();
  });

  await check('screens-pass: why a firmware cannot hold the motor names the form field by its label and the firmware by its name, in the reader\'s language', async () => {
    const robot = golden('23_limit_robot_28krpm.json');
    const NAMED = { zh: '汇川固件无法表示这台电机', en: 'the Inovance firmware cannot hold this motor' };
    for (const [lang, label] of [['zh', '频率基值 f_b（最大频率） = 3.26667 kHz'], ['en', 'Base frequency f_b (drive max.) = 3.26667 kHz']]) {
      const p = await newPage();
      await p.goto(link(robot.input).replace('#', `?lang=${lang}#`));
      await ready(p);
      const sel = 'section.answer .firmware-limits [data-field="raw.FullFreq01"]';
      await p.waitForSelector(sel, { timeout: 30_000 });
      const text = await p.textContent(sel);
      assert(text.includes(label) && !text.includes('drive.base_freq_hz'), `${lang}: "${text}"`);
      // the review's finding names the firmware as the picker does
      const finding = await p.textContent('#panel-review li.finding[data-finding="firmware.inovance"] .msg');
      assert(finding.startsWith(NAMED[lang]), `${lang}: "${finding}"`);
      await p.context().close();
    }
  });

  await check('screens-pass: on a phone the datasheet conversions keep each formula whole and the values on screen; U_dc from the datasheet shows at its field', async () => {
    // The maxon EC 45 flat 50 W as printed: seven conversions (terminal R and L, Kv, the DC bus).
    const g = JSON.parse(readFileSync(join(ROOT, 'tests/golden/datasheets/maxon_ec45flat_50w_24v.json'), 'utf8'));
    const p = await newPage({ context: { viewport: { width: 390, height: 844 } } });
    await p.goto(link(g.input).replace('#', '?lang=zh#'));
    await ready(p);
    await p.waitForFunction(() => document.documentElement.dataset.numbers === 'live', null, { timeout: 30_000 });
    await p.$eval('#panel-datasheet', (e) => e.scrollIntoView());
    await p.waitForSelector('table.conversions [data-key="datasheet.conversions.0.value"]');
    const cells = await p.$$eval('table.conversions tbody tr', (rows) => rows.map((r) => ({
      lines: r.querySelector('code.formula').getClientRects().length,
      right: r.querySelector('[data-key$=".value"]').getBoundingClientRect().right,
    })));
    assert(cells.length === 7, `${cells.length} conversions`);
    assert(cells.every((c) => c.lines <= 3 && c.right <= 390), `formula lines / value right edge: ${JSON.stringify(cells)}`);
    await (await p.$('#panel-datasheet')).screenshot({ path: join(SHOTS, 'screens-pass-390-zh-datasheet.png') });
    // U_dc not typed: its field shows the datasheet's DC bus in use, as the other derived fields do
    assert((await p.getAttribute('input[name="drive.udc_v"]', 'placeholder')) === '= 24', 'U_dc from the datasheet not shown at its field');
    await p.context().close();
  });

  await check('screens-pass: every unit choice shows its whole unit (V/krpm was cut to "V/krpn")', async () => {
    for (const [w, lang] of [[1366, 'en'], [390, 'zh']]) {
      const p = await newPage({ context: { viewport: { width: w, height: 800 } } });
      await p.goto(`${subSrv.url}?lang=${lang}`);
      await ready(p);
      if (w < 1000) await p.click('nav.tabs .inputs-toggle');
      await p.$$eval('aside.inputs details.section', (ds) => ds.forEach((d) => { d.open = true; }));
      // each option's text against the select's inner width less the dropdown arrow (≈ 18 px)
      const cut = await p.$$eval('select.unit', (sels) => {
        const ctx = document.createElement('canvas').getContext('2d');
        return sels.flatMap((s) => {
          const cs = getComputedStyle(s);
          ctx.font = `${cs.fontSize} ${cs.fontFamily}`;
          const room = s.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight) - 18;
          return [...s.options].filter((o) => ctx.measureText(o.text).width > room).map((o) => `${s.dataset.unitFor}: ${o.text} (${Math.round(ctx.measureText(o.text).width)} > ${Math.round(room)} px)`);
        });
      });
      assert(cut.length === 0, `${w} ${lang}: ${cut.join('; ')}`);
      await p.context().close();
    }
  });

  await check('screens-pass: a vendor constant too big names the profile\'s options by their panel labels, and its finding opens the first of them', async () => {
    const mhp = golden('datasheets/rexroth_mhp112a_024.json').input;
    const want = { en: ['Microchip · voltage base', 'Microchip · voltage base, V'], zh: ['Microchip · 电压基值', 'Microchip · 电压基值，V'] };
    for (const width of [390, 900, 1366]) {
      for (const lang of ['en', 'zh']) {
        const p = await newPage({ context: { viewport: { width, height: 900 } } });
        await p.goto(link({ ...mhp, conventions: { firmware: 'microchip' } }).replace('#', `?lang=${lang}#`));
        await ready(p);
        const f = '#panel-review li.finding[data-finding="firmware.microchip"]';
        await p.waitForSelector(f, { timeout: 30_000 });
        const msg = await p.textContent(`${f} .msg`);
        assert(msg.includes(want[lang][0]) && !msg.includes('profiles.'), `${width} ${lang}: "${msg}"`);
        await p.click(`${f} a.change`);
        await p.waitForFunction(() => document.activeElement?.getAttribute('name') === 'profiles.microchip.voltage_base_v', null, { timeout: 10_000 });
        await p.waitForTimeout(300);
        const [label, top, bottom] = await p.$eval('[name="profiles.microchip.voltage_base_v"]', (e) => {
          const r = e.closest('.field').getBoundingClientRect();
          return [e.closest('.field').querySelector('.lbl').textContent, r.top, r.bottom];
        });
        // on screen, below the sticky tabs
        assert(top >= 40 && bottom <= 900, `${width} ${lang}: the field at ${top}..${bottom} px`);
        assert(label === want[lang][1], `${width} ${lang}: label "${label}"`);
        await p.screenshot({ path: join(SHOTS, `screens-pass-${width}-${lang}-option-link.png`) });
        await p.context().close();
      }
    }
  });
}
