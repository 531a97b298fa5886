// `sphereset view ROBOT.urdf SPHERES.yml` in headless Chromium: one solid per link with its
// spheres, placed by the poses; a joint moves the links after it, through the hook and through
// the page's own slider.
import { writeRobot } from './fixtures.mjs';
import {
  canvasShot, check, checkNoErrors, near, openPage, pixelStats, runTest, startView,
} from './harness.mjs';

const close = (a, b) => a.length === b.length && a.every((v, i) => near(v, b[i], 1e-5));

await runTest(async (args, browser) => {
  const robot = writeRobot(args.work);
  const { url } = await startView(args, [robot.urdf, robot.spheres]);
  const { page, errors } = await openPage(browser, url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);

  const scene = await hooks(() => window.sphereset.scene());
  check(scene.kind === 'robot', 'the scene is a robot');
  const links = scene.solids.map((s) => s.link);
  for (const [link, count] of Object.entries(robot.counts)) {
    const k = links.indexOf(link);
    check(k >= 0, `link ${link} is a solid`);
    check(await hooks((i) => window.sphereset.sphereCount(i), k) === count, `${link}: ${count} spheres drawn`);
  }
  const k = links.indexOf('link2');
  const start = await hooks((i) => window.sphereset.linkWorldPosition(i), k);
  check(close(start, robot.link2Origin(0)), `link2 at ${start} at rest`);
  const shot = await pixelStats(browser, await canvasShot(page));
  check(shot.colours > 10, `the picture is not blank (${shot.colours} colours)`);

  await hooks(() => window.sphereset.setJoint('joint1', 0.8));
  const moved = await hooks((i) => window.sphereset.linkWorldPosition(i), k);
  check(close(moved, robot.link2Origin(0.8)), `setJoint(joint1, 0.8) moves link2 to ${moved}`);

  // The slider itself: dragged to -0.5, the page asks the server and applies the poses it gets.
  await page.$eval('input[data-joint="joint1"]', (slider) => {
    slider.value = '-0.5';
    slider.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.waitForFunction(() => {
    const joint = window.sphereset.scene().joints.find((j) => j.name === 'joint1');
    return Math.abs(joint.value + 0.5) < 1e-3;
  }, { timeout: 20000 });
  const dragged = await hooks((i) => window.sphereset.linkWorldPosition(i), k);
  check(close(dragged, robot.link2Origin(Number((await hooks(() => window.sphereset.scene())).joints[0].value))),
    `the joint1 slider moves link2 to ${dragged}`);

  checkNoErrors(errors, 'in normal use');
});
