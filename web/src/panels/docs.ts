// Explainer chapters (docs/zh, docs/en) rendered with the current report. Filled in when the
// chapters exist (issue 5); until then the panel is hidden.
import { h } from '../dom';
import { t } from '../i18n';
import type { Panel } from './panel';

const CHAPTERS = import.meta.glob('../../../docs/{zh,en}/*.md', { query: '?raw', import: 'default', eager: true }) as Record<string, string>;

export function docsAvailable(): boolean {
  return Object.keys(CHAPTERS).length > 0;
}

export const docsPanel: Panel = {
  id: 'docs',
  title: 'p_docs',
  render(el) {
    el.replaceChildren(h('p', {}, t('docsMissing')));
  },
};
