// The panels of the page, in display order. To add a panel: one file in this folder behind the
// `Panel` interface (panel.ts), one line here, its `nav_<id>` and title keys in i18n.ts.
import type { Panel } from './panel';
import { reviewPanel } from './review';
import { datasheetPanel } from './datasheet';
import { basesPanel } from './bases';
import { puPanel } from './pu';
import { vendorPanel } from './vendor';
import { constantsPanel } from './constants';
import { currentPanel } from './current';
import { pllPanel } from './pll';
import { loopPanel } from './loop';
import { qcalcPanel } from './qcalc';
import { codePanel } from './code';
import { conventionsPanel } from './conventions';
import { sweepPanel } from './sweep';
import { provePanel } from './prove';
import { batchPanel } from './batch';
import { vendorsPanel } from './vendors';
import { boardPanel } from './board';
import { fwPanel } from './fw';
import { observerPanel } from './observer';
import { auditPanel } from './audit';
import { acimPanel } from './acim';
import { docsPanel, setPanelRegistry } from './docs';

export const PANELS: Panel[] = [
  reviewPanel, // first: the design review is the page's summary
  datasheetPanel,
  acimPanel,
  basesPanel,
  puPanel,
  vendorPanel,
  constantsPanel,
  currentPanel,
  pllPanel,
  loopPanel,
  qcalcPanel,
  codePanel,
  conventionsPanel,
  sweepPanel,
  provePanel,
  batchPanel,
  vendorsPanel,
  boardPanel,
  fwPanel,
  observerPanel,
  auditPanel,
  docsPanel, // last: the explainer chapters
];
setPanelRegistry(PANELS);

export function panelById(id: string | null): Panel | undefined {
  return PANELS.find((p) => p.id === id);
}
