// Time until the page of `sphereset view` is interactive, for one mesh and its spheres, in
// headless Chromium (the browser tests' harness): the command's start to its URL (load, repair,
// index, certificate), the page's load to window.sphereset.ready (scene, geometry, first frame),
// and one edit's round trip through the page (the server's incremental certificate and the
// redraw). Prints one CSV row.
//   node bench/view_interactive.mjs --cli SPHERESET --node-modules DIR --work DIR \
//     [--chromium CHROMIUM] -- MESH SPHERES
import { performance } from 'node:perf_hooks';

import { parseArgs } from '../tests/browser/harness.mjs';
import { openTimedView } from './view_timing.mjs';

const split = process.argv.indexOf('--');
const [mesh, spheres] = process.argv.slice(split + 1);
process.argv = process.argv.slice(0, split);
const args = parseArgs();

const view = await openTimedView(args, [mesh, spheres], { width: 900, height: 600 });
const { page, errors } = view;
try {
  const info = await page.evaluate(() => {
    const s = window.sphereset.scene();
    return { triangles: s.solids[0].triangles, spheres: s.solids[0].spheres.length,
      first: s.solids[0].spheres[0] };
  });
  const moved = [info.first[0] + 0.1 * info.first[3], info.first[1], info.first[2], info.first[3]];
  const t2 = performance.now();
  await page.evaluate((s) => window.sphereset.setSphere(0, 0, s), moved);
  const edited = performance.now();
  const cert = await page.evaluate(() => window.sphereset.certificate(0));
  if (errors.length) throw new Error(`page errors: ${errors.join(' | ')}`);
  const name = mesh.split('/').pop();
  console.log('mesh,triangles,spheres,serve_s,page_ready_s,interactive_s,edit_ms,server_edit_ms');
  console.log([name, info.triangles, info.spheres, view.serve_s.toFixed(2), view.ready_s.toFixed(2),
    view.interactive_s.toFixed(2), (edited - t2).toFixed(0), (1000 * cert.seconds).toFixed(1)].join(','));
} finally {
  await view.browser.close();
  view.child.kill();
}
process.exit(0);
