// The anywidget front end of pulab_docs.widget.PanelWidget: one <pu-lab-panel> from the site's
// embed.js (which defines the element and sizes it); its reports go back to the Python model.
function attrs(model, el) {
  el.setAttribute('panel', model.get('panel'));
  const lang = model.get('lang');
  if (lang) el.setAttribute('lang', lang); else el.removeAttribute('lang');
  const input = model.get('input');
  if (input && Object.keys(input).length) el.setAttribute('input', JSON.stringify(input));
  else el.removeAttribute('input');
}

/**
 * The site's embed.js, added once as a classic <script src> (it finds the site from its own tag;
 * a classic script of another origin needs no CORS header); resolves once <pu-lab-panel> is defined.
 */
function loadEmbed(src) {
  if (customElements.get('pu-lab-panel')) return Promise.resolve();
  let tag = Array.from(document.scripts).find((s) => s.src === src);
  if (!tag) {
    tag = document.createElement('script');
    tag.src = src;
    document.head.append(tag);
  }
  return new Promise((resolve, reject) => {
    customElements.whenDefined('pu-lab-panel').then(() => resolve());
    tag.addEventListener('error', () => reject(new Error(`pu-lab: could not load ${src}`)));
  });
}

export default {
  async render({ model, el }) {
    await loadEmbed(new URL('embed.js', model.get('site')).href);
    const panel = document.createElement('pu-lab-panel');
    attrs(model, panel);
    panel.addEventListener('pu-lab-report', (e) => {
      model.set('report', e.detail.report);
      model.set('numbers', e.detail.numbers);
      model.save_changes();
    });
    const update = () => attrs(model, panel);
    model.on('change:panel', update);
    model.on('change:lang', update);
    model.on('change:input', update);
    el.append(panel);
    return () => {
      model.off('change:panel', update);
      model.off('change:lang', update);
      model.off('change:input', update);
    };
  },
};
