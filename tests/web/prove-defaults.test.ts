// @vitest-environment happy-dom
// The Prove view's default ranges follow the page's motor (the report's echoed input, derived
// values included) until the user edits a range.
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { provePanel } from '../../web/src/panels/prove';
import { SEED_INPUT, clone, reportKey, type Input } from '../../web/src/state';
import type { PanelContext } from '../../web/src/panels/panel';
import { execFileSync } from 'node:child_process';

/** CPython's report of `input` (happy-dom cannot load the build's own helper). */
const report = (input: Input) => JSON.parse(execFileSync('python3', ['-c', 'import sys, pulab.api as a; print(a.call_json("report", sys.stdin.read()))'],
  { input: reportKey(input), env: { ...process.env, PYTHONPATH: 'py' } }).toString()).report;
const ctxFor = (input: Input): PanelContext => ({
  report: report(input), simReport: null, simError: null, input, client: null, embed: false,
});
const shown = (el: HTMLElement, i: number) => [0, 1].map((k) =>
  Number(el.querySelector<HTMLInputElement>(`input[name="prove.ranges.${i}.${k ? 'hi' : 'lo'}"]`)!.value));

describe('Prove default ranges', () => {
  it('follow a new motor (datasheet-derived rated voltage included) until a range is edited', () => {
    const el = document.createElement('div');
    provePanel.render(el, ctxFor(clone(SEED_INPUT)));
    const emrax = JSON.parse(readFileSync('tests/golden/datasheets/emrax_228_lv.json', 'utf8')).input as Input;
    provePanel.render(el, ctxFor(emrax));
    // Rated current 450 A as typed; rated voltage from the DC bus: 160 V / √2 (SVPWM, RMS line).
    expect(shown(el, 0)).toEqual([225, 900]);
    const u = 160 / Math.SQRT2;
    const [lo, hi] = shown(el, 1);
    expect(Math.abs(lo - u / 2) / (u / 2)).toBeLessThan(5e-3); // 3 significant digits shown
    expect(Math.abs(hi - u * 2) / (u * 2)).toBeLessThan(5e-3);
    // An edited range is the user's: another motor leaves it as typed.
    const loIn = el.querySelector<HTMLInputElement>('input[name="prove.ranges.0.lo"]')!;
    loIn.value = '7';
    loIn.dispatchEvent(new Event('input'));
    provePanel.render(el, ctxFor(clone(SEED_INPUT)));
    expect(shown(el, 0)).toEqual([7, 900]);
  });
  it('Remove and Add act on the rows shown, however often the motor re-renders the panel', () => {
    const el = document.createElement('div');
    const ctx = ctxFor(clone(SEED_INPUT));
    provePanel.render(el, ctx);
    provePanel.render(el, ctx); // the same motor: nothing rebuilt, the buttons keep their rows
    const rows = () => el.querySelectorAll('.pr-range').length;
    const before = rows();
    el.querySelector<HTMLButtonElement>('.pr-range button.pr-remove')!.click();
    expect(rows()).toBe(before - 1);
    el.querySelector<HTMLButtonElement>('button.pr-add')!.click();
    provePanel.render(el, ctx);
    expect(rows()).toBe(before);
  });
  it('a new input chosen for an untyped row takes that input\'s own default range', () => {
    const el = document.createElement('div');
    const ctx = ctxFor(clone(SEED_INPUT));
    provePanel.render(el, ctx);
    const sel = el.querySelector<HTMLSelectElement>('select[name="prove.ranges.0.path"]')!;
    sel.value = 'motor.rs_ohm';
    sel.dispatchEvent(new Event('change'));
    expect(shown(el, 0)).toEqual([0.75, 3]); // the seed's 1.5 Ω, halved and doubled
  });
  it.each([
    ['drive.base_freq_hz', [110, 440]], // left empty: f_b = f_n = 220 Hz, as the report derives it
    ['raw.LD', [30, 120]], // the seed's raw LD = 60 (10 µH units), whole numbers
    ['motor.pole_pairs', [2, 8]],
  ])('%s, empty in the form, starts at the value the report derived: %j', (path, want) => {
    const el = document.createElement('div');
    provePanel.render(el, ctxFor(clone(SEED_INPUT)));
    const sel = el.querySelector<HTMLSelectElement>('select[name="prove.ranges.0.path"]')!;
    sel.value = path;
    sel.dispatchEvent(new Event('change'));
    expect(shown(el, 0)).toEqual(want);
  });
  it('offers only inputs a family proof ranges over (no datasheet or analysis values)', () => {
    const el = document.createElement('div');
    provePanel.render(el, ctxFor(clone(SEED_INPUT)));
    const offered = [...el.querySelectorAll<HTMLOptionElement>('select[name="prove.ranges.0.path"] option')].map((o) => o.value);
    expect(offered).toContain('raw.LD');
    expect(offered.filter((p) => /^(datasheet|analysis|sim)\./.test(p))).toEqual([]);
  });
});
