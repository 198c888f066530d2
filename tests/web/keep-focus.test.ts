// @vitest-environment happy-dom
// A panel rebuilt between two keystrokes (a report arrives, the runtime becomes ready) keeps the
// focus in the box of the same name, the caret where it was.
import { describe, expect, it } from 'vitest';
import { h, keepFocus } from '../../web/src/dom';

const box = (value: string) => h('div', {}, h('input', { name: 'prove.ranges.1.lo', value }), h('select', { name: 'prove.profile' }, h('option', { value: 'ti' }, 'ti')));

describe('keepFocus', () => {
  it('input focused, panel replaced → the new input of that name focused, caret kept', () => {
    const el = h('div', {}, box('15'));
    document.body.append(el);
    const old = el.querySelector('input')!;
    old.focus();
    old.setSelectionRange(1, 1);
    keepFocus(el, () => el.replaceChildren(box('15')));
    const now = el.querySelector('input')!;
    expect(now).not.toBe(old);
    expect(document.activeElement).toBe(now);
    expect([now.selectionStart, now.selectionEnd]).toEqual([1, 1]);
    el.remove();
  });
  it('select focused, panel replaced → the new select focused', () => {
    const el = h('div', {}, box(''));
    document.body.append(el);
    el.querySelector('select')!.focus();
    keepFocus(el, () => el.replaceChildren(box('')));
    expect(document.activeElement).toBe(el.querySelector('select'));
    el.remove();
  });
  it('nothing focused inside → the focus stays where it was', () => {
    const el = h('div', {}, box(''));
    const outside = h('input', { name: 'motor.rs_ohm' });
    document.body.append(el, outside);
    outside.focus();
    keepFocus(el, () => el.replaceChildren(box('')));
    expect(document.activeElement).toBe(outside);
    el.remove();
    outside.remove();
  });
  it('the rebuild moved the focus on purpose inside the panel → left there', () => {
    const el = h('div', {}, box(''));
    document.body.append(el);
    el.querySelector('input')!.focus();
    keepFocus(el, () => el.querySelector('select')!.focus());
    expect(document.activeElement).toBe(el.querySelector('select'));
    el.remove();
  });
});
