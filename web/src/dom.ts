// Tiny DOM builder and the one way numbers from the report are rendered (data-key/data-value).
import katex from 'katex';
import { fmtHex, fmtNum, fmtPct } from './format';
import { has, t, type Key } from './i18n';

type Child = Node | string | number | null | undefined | false | Child[];
type Attrs = Record<string, string | number | boolean | null | undefined | ((ev: Event) => void)>;

/** The handlers h() gave each element, by event type: `morph` hands a kept element the new ones. */
const handlers = new WeakMap<Element, Record<string, (ev: Event) => void>>();
function dispatch(ev: Event): void {
  // currentTarget, not `this`: happy-dom calls a select's change listeners with another `this`.
  handlers.get(ev.currentTarget as Element)?.[ev.type]?.(ev);
}

/**
 * Where a `<select>` is built: a document without a browsing context. Built in the page's own
 * document, a select tells the browser its selection changed as its options arrive, and
 * Chromium's autofill answers such a change by extracting every field of the page with a forced
 * style and layout pass — 47–82 ms of the page's thread during a cold share link (traced), and one
 * more parse of the page's fields in the browser process. Built here, it says nothing until it is
 * inserted (it then joins the page's document with its listeners).
 */
let selectDocument: Document | null = null;

export function h(tag: string, attrs: Attrs = {}, ...children: Child[]): HTMLElement {
  const el = (tag === 'select' ? (selectDocument ??= document.implementation.createHTMLDocument('')) : document).createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === null || v === undefined || v === false) continue;
    if (typeof v === 'function') {
      const type = k.replace(/^on/, '');
      const own = handlers.get(el) ?? {};
      own[type] = v;
      handlers.set(el, own);
      el.addEventListener(type, dispatch);
      el.setAttribute('data-on', Object.keys(own).join(' '));
    } else if (k === 'class') el.className = String(v);
    else if (v === true) el.setAttribute(k, '');
    else el.setAttribute(k, String(v));
  }
  append(el, children);
  return el;
}

function append(el: HTMLElement, children: Child[]): void {
  for (const c of children) {
    if (c === null || c === undefined || c === false) continue;
    if (Array.isArray(c)) append(el, c);
    else el.append(c instanceof Node ? c : String(c));
  }
}

/**
 * A number from the report: `data-key` = its JSON path, `data-value` = full precision (JSON
 * number text), `title` = the same, text = short form. `alias` wraps it in an outer element with a
 * second data-key (e.g. "vendor.Rpm" around "vendor.Rpm.value").
 */
export function num(
  path: string,
  value: unknown,
  opts: { kind?: 'int' | 'float' | 'pct' | 'hex'; type?: string; alias?: string; sig?: number; unit?: string; text?: string; mirror?: boolean } = {},
): HTMLElement {
  const v = typeof value === 'number' ? value : null;
  let text: string;
  if (v === null) text = '…';
  else if (opts.text !== undefined) text = opts.text;
  else if (opts.kind === 'pct') text = fmtPct(v);
  else if (opts.kind === 'hex') text = fmtHex(v, opts.type ?? 'long');
  else text = fmtNum(v, opts.sig ?? 6);
  const cls = `num${opts.kind === 'int' || opts.kind === 'hex' ? ' int' : ''}${v === null ? ' pending' : ''}`;
  // A hex rendering is a second view of a value: it names its source in data-hex-of, so that every
  // data-key in the page is a real path of the report; `mirror` repeats a value shown elsewhere
  // (data-mirror-of), so each data-key appears once.
  const keyAttr = opts.kind === 'hex' ? 'data-hex-of' : opts.mirror ? 'data-mirror-of' : 'data-key';
  const el = h('span', { class: cls, [keyAttr]: path, 'data-value': v === null ? null : JSON.stringify(v), title: v === null ? null : String(v) }, text);
  const inner = opts.unit ? h('span', { class: 'withunit' }, el, h('span', { class: 'u' }, ` ${opts.unit}`)) : el;
  return opts.alias ? h('span', { 'data-key': opts.alias, 'data-value': v === null ? null : JSON.stringify(v) }, inner) : inner;
}

/** Form controls keep what the user did to them (value, focus, selection): never patched. */
const REPLACED = new Set(['INPUT', 'SELECT', 'TEXTAREA', 'OPTION', 'DETAILS', 'IFRAME', 'CANVAS']);

/**
 * Make `old`'s children equal to `fresh`'s by patching in place: nodes of the same kind are kept
 * and only changed text and attributes are written, so a new report costs the browser a layout of
 * the numbers that changed instead of the whole panel (input → numbers). Elements with
 * equal `data-tex` (the same cached formula) are not descended into; form controls are replaced;
 * elements with handlers carry `data-on` (their event types) and get the new handlers; an element
 * with the same `data-keep` as the old one (a figure its panel draws itself) is kept as it is.
 */
export function morph(old: Element, fresh: Element): void {
  let o = old.firstChild;
  let n = fresh.firstChild;
  while (n) {
    const next = n.nextSibling;
    if (!o) {
      old.append(n);
    } else {
      const oNext = o.nextSibling;
      if (o.nodeType !== n.nodeType || o.nodeName !== n.nodeName || REPLACED.has(n.nodeName)) old.replaceChild(n, o);
      else if (o instanceof Element) {
        const keep = (n as Element).getAttribute('data-keep');
        if (keep !== null && keep === o.getAttribute('data-keep')) {
          o = oNext;
          n = next;
          continue;
        }
        // An equal subtree (the usual case: most of a panel is unchanged) is left alone, unless
        // it holds handlers (`data-on`), which must be the new ones (they may close over the report).
        if (!o.isEqualNode(n) || (n as Element).matches('[data-on], :has([data-on])')) patchElement(o, n as Element);
      }
      else if (o.nodeValue !== n.nodeValue) o.nodeValue = n.nodeValue;
      o = oNext;
    }
    n = next;
  }
  while (o) {
    const x = o.nextSibling;
    o.remove();
    o = x;
  }
}

function patchElement(o: Element, n: Element): void {
  const tex = n.getAttribute('data-tex');
  // Read before the attributes are copied: another formula at this place must be redrawn.
  const sameTex = tex !== null && tex === o.getAttribute('data-tex');
  const oa = o.attributes;
  for (let i = oa.length - 1; i >= 0; i--) if (!n.hasAttribute(oa[i].name)) o.removeAttribute(oa[i].name);
  const na = n.attributes;
  for (let i = 0; i < na.length; i++) if (o.getAttribute(na[i].name) !== na[i].value) o.setAttribute(na[i].name, na[i].value);
  const own = handlers.get(n);
  if (own) {
    for (const type of Object.keys(own)) o.addEventListener(type, dispatch);
    handlers.set(o, own);
  } else handlers.delete(o);
  if (sameTex) return;
  morph(o, n);
}

/** Show `children` in `el`, patched in place (morph) when `el` already shows something; the
 * formulas (`tex`) it newly shows are filled in (unless held: `holdFormulas`). */
export function patch(el: HTMLElement, ...children: Child[]): void {
  if (!el.firstChild) append(el, children);
  else morph(el, h('div', {}, children));
  if (!formulasHeld) fillFormulas(el);
}

/** The same items, each the same (===): what a panel drew with has not changed. */
export function sameItems(a: readonly unknown[], b: readonly unknown[]): boolean {
  return a.length === b.length && a.every((x, i) => x === b[i]);
}

/** The name of the form control inside `el` that has the focus (before `el` is rebuilt), or null. */
export function focusedInput(el: HTMLElement): string | null {
  const a = document.activeElement;
  const named = a instanceof HTMLInputElement || a instanceof HTMLTextAreaElement || a instanceof HTMLSelectElement;
  return named && el.contains(a) && a.name ? a.name : null;
}

/**
 * Run `rebuild` (which may replace what `el` shows) and give the focus back to the control of the
 * same name if the rebuild took it away, the caret where it was: a report or the runtime becoming
 * ready re-renders panels between two keystrokes, and the second must land in the same box.
 */
export function keepFocus(el: HTMLElement, rebuild: () => void): void {
  const name = focusedInput(el);
  const before = name ? (document.activeElement as HTMLInputElement | HTMLTextAreaElement) : null;
  const caret = before && 'selectionStart' in before && typeof before.selectionStart === 'number' && isText(before)
    ? [before.selectionStart, before.selectionEnd ?? before.selectionStart] : null;
  rebuild();
  if (!name || (document.activeElement && el.contains(document.activeElement) && document.activeElement !== document.body)) return;
  const again = el.querySelector<HTMLInputElement | HTMLTextAreaElement | HTMLSelectElement>(`[name="${CSS.escape(name)}"]`);
  if (!again) return;
  again.focus();
  if (caret && !(again instanceof HTMLSelectElement) && isText(again)) again.setSelectionRange(caret[0], caret[1]);
}

/** A control whose caret can be set (setSelectionRange throws on number, checkbox, …). */
function isText(e: HTMLInputElement | HTMLTextAreaElement): boolean {
  return e instanceof HTMLTextAreaElement || ['text', 'search', 'url', 'tel', 'password', ''].includes(e.type);
}

/** Flags as coloured chips with a tooltip. */
export function flagChips(flags: unknown): HTMLElement {
  const list = Array.isArray(flags) ? (flags as string[]) : [];
  return h(
    'span',
    { class: 'flags' },
    list.length === 0
      ? h('span', { class: 'flag none' }, '—')
      : list.map((f) =>
          h('span', { class: `flag flag-${f}`, title: has(`flagHelp_${f}`) ? t(`flagHelp_${f}` as Key) : f }, has(`flag_${f}`) ? t(`flag_${f}` as Key) : f),
        ),
  );
}

/** Each `data-tex` key `tex` has handed out: its TeX source, display mode and, once a formula
 * of it has been filled in, KaTeX's markup. */
const formulas = new Map<string, { src: string; display: boolean; markup?: HTMLElement }>();
let formulasHeld = false;

/**
 * KaTeX formula (display or inline), typeset once per source and cached. Returned empty: `patch`
 * fills it in where it is newly shown and keeps a formula already shown (equal `data-tex`), so a
 * new report copies no formula (deep copies of KaTeX's markup were a fifth of a render).
 */
export function tex(src: string, display = false): HTMLElement {
  const key = `${display ? 'D' : 'I'}${src}`;
  if (!formulas.has(key)) formulas.set(key, { src, display });
  return h(display ? 'div' : 'span', { class: 'tex', 'data-tex': key });
}

/** Fill in the empty formulas under `root`, typesetting those not typeset yet. */
function fillFormulas(root: ParentNode): void {
  for (const f of root.querySelectorAll('[data-tex]:empty')) {
    const formula = formulas.get(f.getAttribute('data-tex') ?? '');
    if (!formula) continue;
    if (!formula.markup) {
      formula.markup = h('span');
      formula.markup.innerHTML = katex.renderToString(formula.src, { displayMode: formula.display, throwOnError: false, output: 'html' });
    }
    f.append(...[...formula.markup.childNodes].map((c) => c.cloneNode(true)));
  }
}

/**
 * Leave formulas empty until `releaseFormulas`: the page holds them until its first numbers are
 * on screen. Typesetting the 37 formulas of the calculator's panels took ≈ 40 ms of the page's
 * thread during a cold share link, while Python booted on the same two cores, and none of them
 * is on its first screen.
 */
export function holdFormulas(): void {
  formulasHeld = true;
}

/** Fill in every formula under `root` held so far; from now on `patch` fills them in at once. */
export function releaseFormulas(root: ParentNode): void {
  formulasHeld = false;
  fillFormulas(root);
}

export function table(head: (string | Node)[], rows: (Child[] | HTMLElement)[], cls = ''): HTMLElement {
  return h(
    'table',
    { class: `grid ${cls}` },
    h('thead', {}, h('tr', {}, head.map((x) => h('th', {}, x)))),
    h('tbody', {}, rows.map((r) => (r instanceof HTMLElement ? r : h('tr', {}, r.map((c) => h('td', {}, c)))))),
  );
}

/**
 * Scroll `el` to the top of this document's view. In an iframe (an embed), scrollIntoView would
 * scroll the host page too; there only this document scrolls.
 */
export function scrollToEl(el: Element | null | undefined): void {
  if (!el) return;
  if (window.parent === window) {
    el.scrollIntoView({ block: 'start' });
    return;
  }
  const margin = parseFloat(getComputedStyle(el).scrollMarginTop) || 0;
  window.scrollTo({ top: el.getBoundingClientRect().top + window.scrollY - margin });
}
