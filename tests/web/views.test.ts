// @vitest-environment happy-dom
// The views (tabs) of the page: every panel of the registry is in exactly one view, a panel no view
// lists gets a "more" tab, and a panel asked to scroll into view shows its view.
import { describe, expect, it, vi } from 'vitest';
import { h } from '../../web/src/dom';
import { Layout } from '../../web/src/page/layout';
import { PANELS } from '../../web/src/panels/registry';
import { VIEWS, viewsFor } from '../../web/src/panels/views';
import type { PanelContext } from '../../web/src/panels/panel';
import type { Report } from '../../web/src/generated/report-types';

describe('views', () => {
  it('every registered panel is in exactly one view; the first view holds the review and the firmware integers', () => {
    const listed = VIEWS.flatMap((v) => v.panels);
    for (const p of PANELS) expect(listed.filter((id) => id === p.id)).toEqual([p.id]);
    expect(VIEWS[0].panels.slice(0, 2)).toEqual(['review', 'vendor']);
  });

  it('a panel no view lists gets a "more" view; views without a shown panel are left out', () => {
    const v = viewsFor(['review', 'qcalc', 'unlisted']);
    expect(v.map((x) => [x.id, x.panels])).toEqual([['design', ['review']], ['tools', ['qcalc']], ['more', ['unlisted']]]);
  });

  it('the full page shows one view; scrolling a panel of another view into view shows that view', () => {
    const root = h('div');
    document.body.append(root);
    const layout = new Layout(root, null);
    layout.build(h('header'));
    const shown = () => [...root.querySelectorAll<HTMLElement>('section.panel')].filter((s) => !s.hidden).map((s) => s.dataset.panel);
    expect(shown().sort()).toEqual([...VIEWS[0].panels].sort());
    root.querySelector<HTMLElement>('#panel-pll')?.scrollIntoView();
    expect(shown()).toEqual(['current', 'pll', 'loop', 'fw', 'observer']);
    expect(root.querySelector('nav.tabs a.on')?.getAttribute('data-view')).toBe('loops');
    root.remove();
  });

  it('each view shows its panels in the order its sub-navigation lists them', () => {
    const root = h('div');
    document.body.append(root);
    const layout = new Layout(root, null);
    layout.build(h('header'));
    for (const v of VIEWS.filter((x) => x.id !== 'learn')) {
      layout.showView(v.id);
      const shown = [...root.querySelectorAll<HTMLElement>('section.panel')].filter((s) => !s.hidden).map((s) => s.dataset.panel);
      const nav = [...root.querySelectorAll<HTMLElement>('nav.subtabs a[data-nav]')].map((a) => a.dataset.nav);
      expect(shown).toEqual(v.panels);
      expect(nav).toEqual(v.panels);
    }
    root.remove();
  });

  it('before the first numbers only the shown view is rendered; a hidden view renders when shown or with the first report', () => {
    const root = h('div');
    document.body.append(root);
    const layout = new Layout(root, null);
    layout.build(h('header'));
    const rendered: string[] = [];
    const spies = PANELS.map((p) => vi.spyOn(p, 'render').mockImplementation(() => void rendered.push(p.id)));
    const none: PanelContext = { report: null, simReport: null, simError: null, input: {}, client: null, embed: false };
    layout.renderPanels(none);
    expect([...rendered].sort()).toEqual([...VIEWS[0].panels].sort());
    rendered.length = 0;
    root.querySelector<HTMLElement>('#panel-pll')?.scrollIntoView();
    expect([...rendered].sort()).toEqual(['current', 'fw', 'loop', 'observer', 'pll']);
    // The first report renders every panel still waiting, even in a render asked for a few.
    rendered.length = 0;
    layout.renderPanels({ ...none, report: {} as Report }, ['review']);
    const rest = PANELS.map((p) => p.id).filter((id) => !VIEWS[0].panels.includes(id) && !['current', 'fw', 'loop', 'observer', 'pll'].includes(id));
    expect([...rendered].sort()).toEqual(['review', ...rest].sort());
    spies.forEach((s) => s.mockRestore());
    root.remove();
  });
});
