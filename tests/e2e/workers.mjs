// Helpers shared by e2e suites.

/**
 * Python runtimes (shared or dedicated workers) created in `page`'s browser context from now on
 * (other suites' contexts may still run workers). Returns {kinds, stop()}.
 */
export async function watchWorkers(browser, page) {
  const own = await page.context().newCDPSession(page);
  const { targetInfo } = await own.send('Target.getTargetInfo');
  await own.detach();
  const cdp = await browser.newBrowserCDPSession();
  const kinds = [];
  cdp.on('Target.targetCreated', ({ targetInfo: t }) => {
    if ((t.type === 'shared_worker' || t.type === 'worker') && t.browserContextId === targetInfo.browserContextId) kinds.push(t.type);
  });
  await cdp.send('Target.setDiscoverTargets', { discover: true });
  return { kinds, stop: async () => { await cdp.send('Target.setDiscoverTargets', { discover: false }); await cdp.detach(); } };
}
