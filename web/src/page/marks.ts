// Boot phases for `npm run bench`: the first time each step happened, ms since navigation, as
// <html data-t-…> attributes (e.g. data-t-numbers, data-t-live, data-t-boot-import).
export function mark(step: string, at = performance.now()): void {
  const k = `t${step.replace(/(^|[-_])(\w)/g, (_, _s: string, c: string) => c.toUpperCase())}`;
  const d = document.documentElement.dataset;
  if (d[k] === undefined) d[k] = at.toFixed(0);
}
