// In-page links (why?, panel links, chapter anchors, the nav): handled here because
// location.hash holds the input state and must not change. In an embed, they open the full page.
import { scrollToEl } from '../dom';
import { docTarget, openChapter } from '../panels/docs';
import type { PanelId } from '../panels/panel';
import { openInputs } from './drawer';

export function handleLinks(root: HTMLElement, embed: PanelId | null, showDocs: () => void, showView: (id: string) => void): void {
  root.addEventListener('click', (ev) => {
    const a = (ev.target as HTMLElement).closest<HTMLElement>('[data-why], [data-panel-link], [data-doc-link], [data-field], [data-view], [data-nav]');
    if (!a) return;
    ev.preventDefault();
    const go = (id: string) => scrollToEl(document.getElementById(id));
    if (a.dataset.why) {
      const target = docTarget(a.dataset.why);
      if (!target) return;
      openChapter(target.chapter, target.anchor);
      if (embed) {
        window.open(`./?embed=docs&chapter=${target.chapter}&anchor=${target.anchor}${location.hash}`, '_blank', 'noopener');
        return;
      }
      showDocs();
      go('panel-docs');
    } else if (a.dataset.panelLink) {
      if (embed) {
        window.open(`./${location.hash}`, '_blank', 'noopener');
        return;
      }
      go(a.dataset.panelLink === 'inputs' ? 'app' : `panel-${a.dataset.panelLink}`);
      if (a.dataset.panelLink === 'inputs') {
        openInputs();
        (root.querySelector('.inputs input') as HTMLElement | null)?.focus();
      }
    } else if (a.dataset.docLink) {
      const el = root.querySelector(`[data-anchor="${CSS.escape(a.dataset.docLink)}"]`);
      scrollToEl(el);
    } else if (a.dataset.field) {
      // A review finding's "→ field": the input to change (its section opened), focused; an
      // option of a panel (a vendor's full scale) is shown in its panel, whose view opens first.
      const name = CSS.escape(a.dataset.field);
      const input = root.querySelector<HTMLElement>(`.inputs [name="${name}"]`);
      const inPanel = input ? null : root.querySelector<HTMLElement>(`section.panel [name="${name}"]`);
      if (embed) {
        window.open(`./${location.hash}`, '_blank', 'noopener');
      } else if (input) {
        const sec = input.closest<HTMLDetailsElement>('details.section');
        if (sec) sec.open = true;
        openInputs();
        scrollToEl(input.closest('.field'));
        input.focus();
      } else if (inPanel) {
        scrollToEl(inPanel.closest('section.panel'));
        // after the view's panels have laid out (showing a view moves what is above the field)
        requestAnimationFrame(() => requestAnimationFrame(() => {
          scrollToEl(inPanel.closest('.field'));
          inPanel.focus({ preventScroll: true });
        }));
      }
    } else if (a.dataset.view) {
      // A tab: its view from the top (the answer strip stays the first thing on screen).
      showView(a.dataset.view);
      window.scrollTo({ top: 0 });
    } else if (a.dataset.nav) {
      go(`panel-${a.dataset.nav}`);
    }
  });
}
