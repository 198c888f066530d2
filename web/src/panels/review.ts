// The graded design review (pulab.analyses.review): findings, voltage headroom, the thresholds, and the
// marks it leaves at the value each finding concerns. Every number comes from the report.
import { h, num, patch, table } from '../dom';
import { getLang, t, type Key } from '../i18n';
import type { Finding } from '../generated/report-types';
import type { Panel, PanelContext } from './panel';

const HEADROOM = ['limit_v', 'udc_limit_v', 'bemf_fb_v', 'need_rated_fn_v', 'need_rated_fb_v', 'field_weakening_from_hz'] as const;

/** The message of a finding in the reader's language. */
export function findingText(f: Finding): string {
  return getLang() === 'zh' ? f.message_zh : f.message;
}

/** One finding as a list item: severity chip, message, a link to the input to change. */
export function findingItem(f: Finding): HTMLElement {
  return h('li', { class: `finding sev-${f.severity}`, 'data-finding': f.key },
    h('span', { class: `sev sev-${f.severity}` }, t(`sev_${f.severity}` as Key)), ' ',
    h('span', { class: 'msg' }, findingText(f)), ' ',
    h('a', { class: 'change', href: '#app', 'data-field': f.field, title: `${t('reviewChange')}: ${f.field}` }, '→ ',
      (getLang() === 'zh' ? f.label_zh : f.label) ?? h('code', {}, f.field)));
}

/**
 * The findings for the page: the report's, plus the findings about the simulations (their `key`
 * is in `sim`: the PLL's lock, the shipped firmware's integer current PI) of the simulation report
 * (only that one has simulated), most severe first.
 */
export function allFindings(ctx: Pick<PanelContext, 'report' | 'simReport'>): Finding[] {
  const main = ctx.report?.review?.findings ?? [];
  const sim = ctx.simReport?.review?.findings.filter((f) => f.key.startsWith('sim.')) ?? [];
  const order = ['error', 'warning', 'note'];
  return [...main, ...sim].sort((a, b) => order.indexOf(a.severity) - order.indexOf(b.severity));
}

/** The counts line: "1 errors, 2 warnings, 3 notes". */
export function reviewCounts(findings: Finding[]): string {
  const n = (s: string) => findings.filter((f) => f.severity === s).length;
  return t('reviewCounts', { e: n('error'), w: n('warning'), n: n('note') });
}

/**
 * Mark every rendered value a finding concerns (its data-key): a class by severity and the message
 * as a tooltip. Called after the panels render; a value without a finding loses its old mark.
 */
export function markFindings(root: ParentNode, findings: Finding[]): void {
  for (const el of Array.from(root.querySelectorAll<HTMLElement>('[data-finding-sev]'))) {
    el.removeAttribute('data-finding-sev');
    el.removeAttribute('data-finding-msg');
  }
  for (const f of findings) {
    for (const el of Array.from(root.querySelectorAll<HTMLElement>(`[data-key="${f.key}"]`))) {
      if (el.closest('.review')) continue;
      // The most severe finding wins (findings arrive most severe first).
      if (el.hasAttribute('data-finding-sev')) continue;
      el.setAttribute('data-finding-sev', f.severity);
      el.setAttribute('data-finding-msg', findingText(f));
      el.title = `${t(`sev_${f.severity}` as Key)}: ${findingText(f)}`;
    }
  }
}

export const reviewPanel: Panel = {
  id: 'review',
  title: 'p_review',
  pure: true,
  render(el, ctx) {
    const report = ctx.report;
    if (!report?.review) {
      patch(el, h('p', { class: 'note' }, '…'));
      return;
    }
    const rv = report.review;
    const findings = allFindings(ctx);
    const hr = rv.headroom;
    const thr = rv.thresholds;
    patch(el, h('div', { class: 'review' },
      h('p', { class: 'counts' }, reviewCounts(findings)),
      findings.length
        ? h('ul', { class: 'findings' }, findings.map(findingItem))
        : h('p', { class: 'ok' }, t('reviewQuiet')),
      // an induction motor's review has neither (docs/contract.md, "Induction motor")
      hr && h('h3', {}, t('headroomTitle')),
      hr && table([t('quantity'), t('value'), t('unit')], HEADROOM.map((k) => [
        t(`hr_${k}` as Key), hr[k] === null ? '—' : num(`review.headroom.${k}`, hr[k], { sig: 6 }), k === 'field_weakening_from_hz' ? 'Hz' : 'V']), 'headroom'),
      thr && h('details', { class: 'thresholds' }, h('summary', {}, t('reviewThresholds')),
        table([t('quantity'), t('sev_note'), t('sev_warning'), t('sev_error')], Object.keys(thr).map((k) => [
          t(`thr_${k}` as Key),
          ...(['note', 'warning', 'error'] as const).map((s) => num(`review.thresholds.${k}.${s}`, thr[k][s] ?? null, { text: thr[k][s] === undefined ? '—' : String(thr[k][s]) })),
        ]), 'thresholds')),
    ));
  },
};
