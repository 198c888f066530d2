// @vitest-environment happy-dom
// dom.morph: a new report patches a pure panel in place. Named by what is rendered
// before and after, and what must hold of the patched DOM.
import { describe, expect, it } from 'vitest';
import { h, holdFormulas, morph, patch as show, releaseFormulas, tex } from '../../web/src/dom';

/** Render `before` into a host, then morph it to `after`; returns the host and its old first child. */
function patch(before: () => HTMLElement[], after: () => HTMLElement[]): { host: HTMLElement; first: ChildNode | null } {
  const host = h('div', {}, ...before());
  const first = host.firstChild;
  morph(host, h('div', {}, ...after()));
  return { host, first };
}

describe('morph: the host ends up equal to the new render', () => {
  it.each([
    ['a changed number', () => [h('p', {}, h('span', { 'data-key': 'a', 'data-value': '1' }, '1'))], () => [h('p', {}, h('span', { 'data-key': 'a', 'data-value': '2' }, '2'))]],
    ['an attribute added and one removed', () => [h('span', { class: 'x', title: 't' }, 'v')], () => [h('span', { class: 'y', 'data-value': '3' }, 'v')]],
    ['rows appended', () => [h('table', {}, h('tr', {}, 'r1'))], () => [h('table', {}, h('tr', {}, 'r1'), h('tr', {}, 'r2'), h('tr', {}, 'r3'))]],
    ['rows removed', () => [h('ul', {}, h('li', {}, 'a'), h('li', {}, 'b'), h('li', {}, 'c'))], () => [h('ul', {}, h('li', {}, 'a'))]],
    ['another tag at the same place', () => [h('p', {}, 'x'), h('span', {}, 'y')], () => [h('p', {}, 'x'), h('div', {}, 'y'), h('b', {}, 'z')]],
    ['text and elements interleaved', () => [h('p', {}, 'a', h('b', {}, '1'), 'c')], () => [h('p', {}, 'A', h('i', {}, '1'), 'c', 'd')]],
    ['everything removed', () => [h('p', {}, 'x'), h('p', {}, 'y')], () => []],
  ])('%s', (_name, before, after) => {
    const { host } = patch(before, after);
    expect(host.innerHTML).toBe(h('div', {}, ...after()).innerHTML);
  });
});

describe('morph: what is kept, replaced or skipped', () => {
  it('a changed number: the same element, the new text and data-value', () => {
    const { host, first } = patch(
      () => [h('span', { 'data-key': 'base.Z_b', 'data-value': '11.3' }, '11.3')],
      () => [h('span', { 'data-key': 'base.Z_b', 'data-value': '5.66' }, '5.66')]);
    expect(host.firstChild).toBe(first);
    expect((host.firstChild as HTMLElement).dataset.value).toBe('5.66');
  });
  it('a form control is replaced, not patched (it keeps what the user did to it otherwise)', () => {
    const { host, first } = patch(() => [h('input', { name: 'a', value: '1' })], () => [h('input', { name: 'a', value: '2' })]);
    expect(host.firstChild).not.toBe(first);
    expect((host.firstChild as HTMLInputElement).getAttribute('value')).toBe('2');
  });
  it('equal data-tex (the same cached formula): the subtree is not walked', () => {
    const { host } = patch(() => [h('span', { 'data-tex': 'Ix' }, 'old render')], () => [h('span', { 'data-tex': 'Ix' }, 'new render')]);
    expect(host.textContent).toBe('old render');
  });
  it('an equal element with a handler: kept, and a click runs the new handler', () => {
    const calls: string[] = [];
    const { host, first } = patch(
      () => [h('p', {}, h('button', { onclick: () => calls.push('old report') }, 'copy'))],
      () => [h('p', {}, h('button', { onclick: () => calls.push('new report') }, 'copy'))]);
    expect(host.firstChild).toBe(first);
    (host.querySelector('button') as HTMLButtonElement).click();
    expect(calls).toEqual(['new report']);
  });
  it('a handler that the new render no longer has is gone', () => {
    const calls: string[] = [];
    const { host } = patch(() => [h('a', { onclick: () => calls.push('old') }, 'x')], () => [h('a', {}, 'x')]);
    (host.querySelector('a') as HTMLElement).click();
    expect(calls).toEqual([]);
  });
  it('the same data-keep (a figure its panel draws): the old element and its drawing stay', () => {
    const drawn = h('div', { class: 'figure', 'data-keep': 'plot' }, h('svg', {}, 'curve'));
    const host = h('div', {}, h('p', {}, '1'), drawn);
    morph(host, h('div', {}, h('p', {}, '2'), h('div', { class: 'figure', 'data-keep': 'plot' })));
    expect(host.lastChild).toBe(drawn);
    expect(host.innerHTML).toBe('<p>2</p><div class="figure" data-keep="plot"><svg>curve</svg></div>');
  });
  it('another data-keep at that place: patched like any element (the new, empty figure)', () => {
    const host = h('div', {}, h('div', { 'data-keep': 'bode-pll' }, 'drawn'));
    morph(host, h('div', {}, h('div', { 'data-keep': 'bode-speed' })));
    expect(host.innerHTML).toBe('<div data-keep="bode-speed"></div>');
  });
});

describe('patch: formulas (tex) filled where newly shown, kept where already shown', () => {
  it.each([
    ['empty host, a formula → KaTeX markup', [], ['x^2'], (host: HTMLElement) => expect(host.querySelector('.katex')).not.toBeNull()],
    ['the same formula again → the same KaTeX nodes (not copied)', ['x^2'], ['x^2'], (host: HTMLElement, before: Element | null) => expect(host.querySelector('.katex')).toBe(before)],
    ['another formula at its place → that formula\'s markup', ['x^2'], ['y_3'], (host: HTMLElement) => expect(host.textContent).toContain('y')],
  ])('%s', (_name, before, after, check) => {
    const host = h('div');
    if (before.length) show(host, ...before.map((src) => tex(src)));
    const was = host.querySelector('.katex');
    show(host, ...after.map((src) => tex(src)));
    expect(host.querySelectorAll('[data-tex]:empty').length).toBe(0);
    check(host, was);
  });
});

describe('formulas held until the first numbers are on screen', () => {
  it('held: shown empty, typeset by none; released: every one filled in, and later ones at once', () => {
    holdFormulas();
    const host = h('div');
    const root = h('div', {}, host);
    try {
      show(host, tex('a_{held}'), h('p', {}, tex('\\frac{b}{c}', true)));
      expect(host.querySelectorAll('[data-tex]:empty').length).toBe(2);
      expect(host.querySelector('.katex')).toBeNull();
    } finally {
      releaseFormulas(root);
    }
    expect(host.querySelectorAll('[data-tex]:empty').length).toBe(0);
    expect(host.querySelectorAll('.katex').length).toBe(2);
    expect(host.querySelector('.katex-display')).not.toBeNull();
    show(host, tex('a_{held}'), h('p', {}, tex('\\frac{b}{c}', true)), tex('d_{after}'));
    expect(host.querySelectorAll('[data-tex]:empty').length).toBe(0);
    expect(host.textContent).toContain('after');
  });
});

describe('h: a select is built outside the page\'s document', () => {
  it('its options arrive there; inserted, it joins the page with its value and handlers', () => {
    const changed: string[] = [];
    const sel = h('select', { name: 'unit', onchange: (ev: Event) => changed.push((ev.target as HTMLSelectElement).value) },
      h('option', { value: 'a' }, 'A'), h('option', { value: 'b', selected: true }, 'B')) as HTMLSelectElement;
    expect(sel.ownerDocument).not.toBe(document);
    expect(sel.value).toBe('b');
    const host = h('div');
    document.body.append(host);
    try {
      host.append(sel);
      expect(sel.ownerDocument).toBe(document);
      expect(sel instanceof HTMLSelectElement).toBe(true);
      expect(sel.value).toBe('b');
      sel.value = 'a';
      sel.dispatchEvent(new Event('change'));
      expect(changed).toEqual(['a']);
      expect(document.querySelector('select[name="unit"]')).toBe(sel);
    } finally {
      host.remove();
    }
  });
});
