// What the page says about a linked or stored state it could not use as it was (state-check.ts):
// a note at each named field, and a banner for the rest (the whole link, unknown keys). Text only.
import { h } from './dom';
import { ALL_FIELDS, SECTIONS } from './fields';
import { t } from './i18n';
import type { Initial } from './state';
import type { StateProblem } from './state-check';

/** Paths with a message element of their own in the form: every field and every section. */
const FIELD_PATHS = new Set([...ALL_FIELDS.map((f) => f.path), ...SECTIONS.map((s) => s.id)]);

function reason(p: StateProblem): string {
  const got = p.got === 'an object' ? t('state_got_object') : p.got === 'a list' ? t('state_got_list') : p.got;
  return t(`state_reason_${p.reason}`, { got });
}

/** Notes for fields and sections of the form: path → "from the link: wrong type …; the default is used". */
export function fieldNotes(init: Initial): Map<string, string> {
  const out = new Map<string, string>();
  for (const p of init.problems)
    if (FIELD_PATHS.has(p.path)) out.set(p.path, t(p.origin === 'url' ? 'state_note_url' : 'state_note_storage', { reason: reason(p) }));
  return out;
}

/** The banner (role=alert), or null when the state was used as it was. */
export function stateBanner(init: Initial, onDismiss: () => void): HTMLElement | null {
  if (!init.problems.length) return null;
  const head = [];
  if (init.linkBroken)
    head.push(t(init.source === 'url' ? 'state_link_partly' : 'state_link_unusable', { shown: t(`state_shown_${init.source}`) }), ' ', t('state_link_kept'));
  else head.push(t('state_storage_partly'));
  return h('div', { class: 'state-banner', role: 'alert', 'data-state-problems': init.problems.length },
    h('p', {}, ...head),
    h('ul', {}, init.problems.map((p) => h('li', { 'data-problem': p.path }, h('code', {}, p.path), `: ${reason(p)}`))),
    h('button', { type: 'button', class: 'state-dismiss', onclick: onDismiss }, t('state_dismiss')));
}
