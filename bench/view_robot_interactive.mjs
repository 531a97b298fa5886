// The page of `sphereset view` for a robot of many links, in headless Chromium (the browser
// tests' harness): the command's start to its URL (the robot read, each link's solid made and
// certified), the page's load to window.sphereset.ready, and the round trips through the page's
// own functions until the frame is drawn: ROUNDS edits (one sphere of each link in turn grown
// by 1%: the request, the server's incremental certificate and self-collision pairs, the
// redraw) and ROUNDS joint moves (the server's kinematics and pairs, the redraw). Prints one
// CSV row.
//   node bench/view_robot_interactive.mjs --cli SPHERESET --node-modules DIR --work DIR \
//     [--chromium CHROMIUM] -- ROBOT.urdf SPHERES.yml [--package-path DIR]
import { performance } from 'node:perf_hooks';

import { parseArgs } from '../tests/browser/harness.mjs';
import { openTimedView } from './view_timing.mjs';

const split = process.argv.indexOf('--');
const viewArgs = process.argv.slice(split + 1);
process.argv = process.argv.slice(0, split);
const args = parseArgs();
const rounds = Number(process.env.ROUNDS || 40);  // edits, and joint moves

const median = (values) => {
  const v = [...values].sort((a, b) => a - b);
  return v[Math.floor(v.length / 2)];
};

const view = await openTimedView(args, viewArgs, { width: 1200, height: 800 });
const { page, errors } = view;
try {
  const info = await page.evaluate(() => {
    const s = window.sphereset.scene();
    return { links: s.solids.length, spheres: s.solids.reduce((n, x) => n + x.spheres.length, 0),
      joints: s.joints.map((j) => [j.name, j.lower, j.upper]) };
  });

  const edits = [];
  for (let i = 0; i < rounds; i++) {
    const k = i % info.links;
    const start = performance.now();
    await page.evaluate((solid) => {
      const s = window.sphereset.scene().solids[solid].spheres[0];
      return window.sphereset.setSphere(solid, 0, [s[0], s[1], s[2], s[3] * 1.01]);
    }, k);
    edits.push(performance.now() - start);
  }
  const poses = [];
  for (let i = 0; i < rounds; i++) {
    const [name, lower, upper] = info.joints[i % info.joints.length];
    const value = lower + ((i + 1) / (rounds + 1)) * (upper - lower);
    const start = performance.now();
    await page.evaluate((n, v) => window.sphereset.setJoint(n, v), name, value);
    poses.push(performance.now() - start);
  }
  if (errors.length) throw new Error(`page errors: ${errors.join(' | ')}`);
  console.log('robot,links,spheres,serve_s,page_ready_s,interactive_s,edit_median_ms,edit_max_ms,pose_median_ms,pose_max_ms');
  console.log([viewArgs[0].split('/').pop(), info.links, info.spheres, view.serve_s.toFixed(2),
    view.ready_s.toFixed(2), view.interactive_s.toFixed(2),
    median(edits).toFixed(0), Math.max(...edits).toFixed(0), median(poses).toFixed(0),
    Math.max(...poses).toFixed(0)].join(','));
} finally {
  await view.browser.close();
  view.child.kill();
}
process.exit(0);
