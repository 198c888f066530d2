import { h, num, patch, table } from '../dom';
import { getLang, t } from '../i18n';
import { fmtPct } from '../format';
import type { Panel } from './panel';

export const constantsPanel: Panel = {
  id: 'constants',
  title: 'p_constants',
  pure: true,
  render(el, { report }) {
    const cs = report?.constants ?? {};
    const keys = Object.keys(cs).length ? Object.keys(cs) : ['18597', '3678', '2316'];
    patch(el,
      table(
        [t('value'), t('expression'), t('exact'), t('relError'), t('usedIn'), t('derivation')],
        keys.map((k) => {
          const c = cs[k];
          const p = `constants.${k}`;
          return [
            num(`${p}.value`, c?.value, { kind: 'int', alias: p }),
            h('code', {}, c?.expression ?? ''),
            num(`${p}.exact`, c?.exact, { sig: 10 }),
            num(`${p}.rel_error`, c?.rel_error, { text: c ? fmtPct(c.rel_error * 100) : undefined }),
            c?.used_in ?? '',
            h('span', { class: 'deriv' }, (getLang() === 'zh' ? c?.derivation_zh : c?.derivation) ?? ''),
          ];
        }),
        'constants',
      ),
    );
  },
};
