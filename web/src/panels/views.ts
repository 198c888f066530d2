// The page's views: tabs that each show a few panels, so the page is a task flow (the answer, then
// the firmware, the loops, the tools, the explainer) and not every panel in a row. To add a panel
// to a view: its id in `panels` below (a panel in no view gets the "More" tab of its own); to add a
// view: one entry here and its `view_<id>` label in web/src/i18n/screens.ts.
import type { PanelId } from './panel';

export interface View {
  id: string;
  panels: PanelId[];
}

export const VIEWS: View[] = [
  // First: the answer (review, the firmware integers) and what it is built from.
  { id: 'design', panels: ['review', 'vendor', 'acim', 'bases', 'pu', 'datasheet'] },
  { id: 'firmware', panels: ['vendors', 'board', 'constants', 'code', 'audit'] },
  { id: 'loops', panels: ['current', 'pll', 'loop', 'fw', 'observer'] },
  { id: 'tools', panels: ['qcalc', 'conventions', 'sweep', 'prove', 'batch'] },
  { id: 'learn', panels: ['docs'] },
];

/** The views of a page that shows `panels`: the registry's, without panels not shown and views
 * left empty, plus "more" for panels no view lists. */
export function viewsFor(panels: PanelId[]): View[] {
  const listed = new Set(VIEWS.flatMap((v) => v.panels));
  const out = VIEWS.map((v) => ({ id: v.id, panels: v.panels.filter((p) => panels.includes(p)) })).filter((v) => v.panels.length);
  const rest = panels.filter((p) => !listed.has(p));
  return rest.length ? [...out, { id: 'more', panels: rest }] : out;
}
