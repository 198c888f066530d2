// The answer at the top of every screen: the integers of the firmware the reader ships (picked
// here) and the review's summary. Its numbers carry data-key like the panels' (the page's only
// repeated data-keys, equal values); a firmware that cannot hold the motor says why here too, with the same box as its panel.
import { h, num, patch } from '../dom';
import { t } from '../i18n';
import { VENDOR_NAMES, type AcimProfile, type ProfileReport } from '../generated/report-types';
import type { PanelContext } from '../panels/panel';
import { limitsBox } from '../panels/limits';
import { shippedProfileReport } from '../panels/vendors';
import { VENDORS, vendorName, type Vendor } from '../vendors';
import { allFindings, reviewCounts } from '../panels/review';

/** The firmware the reader ships: the input's `conventions.firmware` (the review grades by it). */
export function shippedProfile(ctx: Pick<PanelContext, 'input'>): Vendor {
  const v = ctx.input.conventions?.firmware;
  return (VENDORS as readonly unknown[]).includes(v) ? (v as Vendor) : 'inovance';
}

function chip(name: string, path: string, value: number | undefined, bad = false): HTMLElement {
  // data-key, not a mirror: the strip is on every tab, so a test (or a reader of the DOM) that
  // waits for a number to be visible finds it here whichever tab is open.
  return h('span', { class: `int-chip${bad ? ' bad' : ''}` }, h('code', {}, name), ' ', num(path, value, { kind: 'int' }));
}

function notHeld(name: string): HTMLElement {
  return h('span', { class: 'int-chip na' }, h('code', {}, name), ' ', h('span', { class: 'num na' }, t('fw_not_held')));
}

/** Inovance: the vendor integers and the current PI integers of the page's own report. */
function inovanceChips(ctx: PanelContext): HTMLElement[] {
  const r = ctx.report;
  const missing = new Set(r?.firmware?.inovance?.problems.flatMap((p) => p.results) ?? []);
  const ints = VENDOR_NAMES.map((n) => (missing.has(n) ? notHeld(n)
    : chip(n, `vendor.${n}.value`, r?.vendor?.[n]?.value, r?.vendor?.[n]?.flags.some((f) => f === 'wrap' || f === 'store'))));
  const pi = (['pm_kp', 'pm_ki'] as const).map((k) => chip(k, `current_pi.d.${k}`, r?.current_pi?.d?.[k]));
  return [...ints, ...pi];
}

/** Another vendor: every constant of its profile (vendors.ts shippedProfileReport). */
function profileChips(p: ProfileReport | undefined, v: Vendor): HTMLElement[] {
  if (!p) return [h('span', { class: 'num pending' }, t('answerPending'))];
  return Object.entries(p.constants).map(([k, c]) => chip(k, `profiles.${v}.constants.${k}.value`, c.value, c.flags.some((f) => f === 'out_of_range' || f === 'saturate')));
}

/**
 * The review in one line, a link to its panel: plain with notes only; with errors or warnings
 * marked as a warning (class `warnings`, empty otherwise). The findings themselves are listed once,
 * in the review panel (first in the first view, right below).
 */
function reviewLine(ctx: PanelContext): HTMLElement[] {
  const all = allFindings(ctx);
  const serious = ctx.report !== null && all.some((f) => f.severity !== 'note');
  const line = h('a', { class: 'counts', href: '#panel-review', 'data-nav': 'review' }, `${t('answerReview')}: `, ctx.report ? reviewCounts(all) : '…');
  return serious ? [h('div', { class: 'warnings' }, line)] : [line, h('div', { class: 'warnings' })];
}

/** An induction motor: the current-PI integers for Inovance, the C floats of a vendor with an
 * induction-motor profile (the page's own report holds them), else that it has none. */
function acimChips(ctx: PanelContext, v: Vendor): HTMLElement[] {
  const r = ctx.report!;
  if (v === 'inovance') return (['pm_kp', 'pm_ki'] as const).map((k) => chip(k, `current_pi.d.${k}`, r.current_pi?.d?.[k]));
  const p = (r.profiles as unknown as Record<string, AcimProfile> | undefined)?.[v];
  if (!p?.available || !p.constants) return [h('span', { class: 'num na' }, t('acimNoProfile'))];
  return Object.entries(p.constants).map(([k, c]) => h('span', { class: 'int-chip' }, h('code', {}, k), ' ',
    num(`profiles.${v}.constants.${k}.value`, c.value, { sig: 9 })));
}

/** Render the strip into `el`; `again` renders it once more (a profile's report arrived); `pick`
 * sets the shipped firmware in the input. */
export function renderAnswer(el: HTMLElement, ctx: PanelContext, again: () => void, pick: (v: Vendor) => void): void {
  const v = shippedProfile(ctx);
  const acim = Boolean(ctx.report?.acim);
  const other = v === 'inovance' || acim ? null : shippedProfileReport(ctx, v, again);
  const picker = h('select', {
    name: 'answer.profile', 'aria-label': t('answerProfile'),
    onchange: (ev: Event) => pick((ev.target as HTMLSelectElement).value as Vendor),
  }, VENDORS.map((x) => h('option', { value: x, selected: x === v }, vendorName(x))));
  // The picker and the review's line, the integers, then why the firmware cannot hold the motor.
  patch(el,
    h('div', { class: 'answer-head' },
      h('label', { class: 'answer-profile' }, h('span', {}, t('answerProfile')), picker),
      reviewLine(ctx)),
    h('div', { class: 'answer-ints', 'data-profile': v },
      acim
        ? h('div', { class: 'chips', 'aria-label': t('answerIntegers') }, acimChips(ctx, v),
          h('a', { class: 'more', href: '#panel-acim', 'data-nav': 'acim' }, t('answerAllIntegers')))
        : h('div', { class: 'chips', 'aria-label': t('answerIntegers') }, v === 'inovance' ? inovanceChips(ctx) : profileChips(other?.profile, v),
          h('a', { class: 'more', href: `#panel-${v === 'inovance' ? 'vendor' : 'vendors'}`, 'data-nav': v === 'inovance' ? 'vendor' : 'vendors' }, t('answerAllIntegers'))),
      acim ? null : limitsBox(v, v === 'inovance' ? ctx.report?.firmware?.inovance : other?.status)),
  );
}
