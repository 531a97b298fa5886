// The README's picture of `sphereset view`: spot with 32 fitted spheres, the three largest shrunk
// by a quarter so that the certificate finds gaps (magenta triangles, "not covered"), in headless
// Chromium.
//   node scripts/view_screenshot.mjs --cli build/apps/sphereset \
//     --node-modules build/web/npm/node_modules --work out/view_screenshot -- MESH SPHERES OUT.png
import { launchBrowser, parseArgs, startView } from '../tests/browser/harness.mjs';

const split = process.argv.indexOf('--');
const [mesh, spheres, png] = process.argv.slice(split + 1);
process.argv = process.argv.slice(0, split);
const args = parseArgs();
const { child, url } = await startView(args, [mesh, spheres, '--output', `${args.work}/edited.json`]);
const browser = await launchBrowser(args);
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 720 });
  await page.goto(url, { waitUntil: 'load' });
  await page.evaluate(() => window.sphereset.ready);
  // Three hand edits, each certified by the server in turn.
  await page.evaluate(async () => {
    const set = window.sphereset.scene().solids[0].spheres;
    const largest = set.map((s, i) => [s[3], i]).sort((a, b) => b[0] - a[0]).slice(0, 3);
    for (const [, k] of largest) {
      const s = set[k];
      await window.sphereset.setSphere(0, k, [s[0], s[1], s[2], 0.75 * s[3]]);
    }
  });
  await page.screenshot({ path: png });
  console.log(`wrote ${png}`);
} finally {
  await browser.close();
  child.kill();
}
process.exit(0);
