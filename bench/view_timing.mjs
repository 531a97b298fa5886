// What the view benchmarks share (bench/view_interactive.mjs, bench/view_robot_interactive.mjs):
// `sphereset view ARGS` started and its page opened in headless Chromium, timed from the
// command's start to its URL (serve) and from the page's load to window.sphereset.ready.
import { performance } from 'node:perf_hooks';

import { launchBrowser, startView } from '../tests/browser/harness.mjs';

// Resolves with { browser, child, page, errors (page errors), serve_s, ready_s, interactive_s }
// (interactive: serve and ready, without the browser's own start between them).
export async function openTimedView(args, viewArgs, viewport) {
  const t0 = performance.now();
  const { url, child } = await startView(args, viewArgs);
  const served = performance.now();
  const browser = await launchBrowser(args);
  const page = await browser.newPage();
  await page.setViewport(viewport);
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  const t1 = performance.now();
  await page.goto(url, { waitUntil: 'load' });
  await page.evaluate(() => window.sphereset.ready);
  const ready = performance.now();
  return {
    browser, child, page, errors,
    serve_s: (served - t0) / 1000,
    ready_s: (ready - t1) / 1000,
    interactive_s: (served - t0 + ready - t1) / 1000,
  };
}
