// @vitest-environment happy-dom
// Layout.settle: once the first live numbers are shown, the pure panels are rendered
// WARM_RENDERS more times into detached elements while idle (the page itself is not touched),
// so that the first keystrokes' renders run optimized code.
import { afterEach, describe, expect, it, vi } from 'vitest';
import { h } from '../../web/src/dom';
import { Layout } from '../../web/src/page/layout';
import { PANELS } from '../../web/src/panels/registry';
import type { PanelContext } from '../../web/src/panels/panel';

const ctx: PanelContext = { report: null, simReport: null, simError: null, input: {}, client: null, embed: false };

afterEach(() => {
  vi.restoreAllMocks();
  vi.useRealTimers();
});

describe('warm renders after the first live numbers', () => {
  it.each([
    { name: 'a pure panel (bases)', id: 'bases', embed: null, times: 20 },
    { name: 'a panel with its own state (code)', id: 'code', embed: null, times: 0 },
    { name: 'a pure panel embedded alone (?embed=bases: no form to type in)', id: 'bases', embed: 'bases', times: 0 },
  ])('$name → rendered $times more times, never into the page', ({ id, embed, times }) => {
    vi.useFakeTimers();
    vi.stubGlobal('requestIdleCallback', (f: () => void) => setTimeout(f, 1));
    const root = h('div');
    document.body.append(root);
    const layout = new Layout(root, embed);
    layout.build(h('header'));
    const panel = PANELS.find((p) => p.id === id)!;
    const shown = root.querySelector(`#panel-${id} .panel-body`)!;
    const into: Element[] = [];
    vi.spyOn(panel, 'render').mockImplementation((el) => void into.push(el));
    layout.settle(ctx);
    vi.advanceTimersByTime(1000);
    expect(into.length).toBe(times);
    expect(into.filter((el) => el === shown || el.isConnected)).toEqual([]);
    expect(root.querySelector('main.panels.settled')).not.toBeNull();
  });
});
