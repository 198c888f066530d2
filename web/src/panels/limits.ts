// What one firmware cannot hold for this motor (report.firmware.NAME, docs/contract.md
// "Firmware limits"): shown at that firmware's own panel, never as an input error.
import { h } from '../dom';
import { getLang, t } from '../i18n';
import type { FirmwareStatus } from '../generated/report-types';

/** The box listing a firmware's problems, or null when it holds the motor. */
export function limitsBox(name: string, status: FirmwareStatus | undefined): HTMLElement | null {
  if (!status || status.representable) return null;
  const zh = getLang() === 'zh';
  return h('div', { class: 'firmware-limits', role: 'note', 'data-firmware': name },
    h('p', { class: 'lbl' }, t('fw_cannot_hold')),
    h('ul', {}, status.problems.map((p) => {
      const message = zh ? p.message_zh : p.message;
      // The field's name once: most messages begin with it already.
      const named = message.includes(p.field.split('.').pop() ?? p.field);
      return h('li', { 'data-field': p.field },
        named ? null : [h('code', {}, p.field), ' '], message,
        h('div', { class: 'hint' }, zh ? p.advice_zh : p.advice));
    })));
}
