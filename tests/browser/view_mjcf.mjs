// `sphereset view ROBOT.xml SPHERES.yml` for an MJCF robot (read by MuJoCo) in headless
// Chromium: the links MuJoCo compiled, a slider per hinge and slide joint (none for the ball
// joint), the j2 slider starting at the joint's ref, and a real mouse click on the j1 slider
// moving link2 where the hinge's anchor (0.01 m off the axis of link1's frame) puts it.
import path from 'node:path';
import {
  check, checkNoErrors, near, openPage, runCli, runTest, startView,
} from './harness.mjs';

await runTest(async (args, browser) => {
  const arm = path.resolve(path.dirname(new URL(import.meta.url).pathname),
    '../data/robot/mjcf/arm.xml');
  const spheres = path.join(args.work, 'arm_spheres.yml');
  runCli(args, ['robot', arm, '--default-link-spheres', '2', '--quality', 'fast',
    '--collision-samples', '100', '-o', spheres, '-q']);
  const { url } = await startView(args, [arm, spheres]);
  const { page, errors } = await openPage(browser, url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);

  const scene = await hooks(() => window.sphereset.scene());
  check(scene.kind === 'robot', 'the scene is a robot');
  const names = scene.joints.map((j) => j.name).sort();
  check(JSON.stringify(names) === JSON.stringify(['fl', 'fr', 'j1', 'j2', 'wx', 'wy']),
    `sliders for the hinge and slide joints: ${names}`);
  for (const name of names) {
    check(await page.$(`input[data-joint="${name}"]`) !== null, `a slider for ${name}`);
  }
  const j2 = scene.joints.find((j) => j.name === 'j2');
  check(near(j2.value, (10 * Math.PI) / 180, 1e-9), `j2 starts at its ref, 10 degrees (${j2.value})`);

  // link2's origin at j1 = q: (0, 0, 0.52) + Rz(15°) (0.01 (1 - cos q), -0.01 sin q, 0).
  const k = scene.solids.map((s) => s.link).indexOf('link2');
  check(k >= 0, 'link2 is a solid');
  const expected = (q) => {
    const a = (15 * Math.PI) / 180;
    const x = 0.01 * (1 - Math.cos(q));
    const y = -0.01 * Math.sin(q);
    return [Math.cos(a) * x - Math.sin(a) * y, Math.sin(a) * x + Math.cos(a) * y, 0.52];
  };
  const close = (p, q) => p.every((v, i) => Math.abs(v - q[i]) < 1e-6);
  const rest = await hooks((i) => window.sphereset.linkWorldPosition(i), k);
  check(close(rest, expected(0)), `link2 at ${rest} at rest`);

  // A click at 90 % of the j1 slider's track: the browser sets the value, the page asks the
  // server, and the pose it gets back places link2.
  const slider = await page.$('input[data-joint="j1"]');
  await slider.scrollIntoView();
  const box = await slider.boundingBox();
  await page.mouse.click(box.x + 0.9 * box.width, box.y + box.height / 2);
  await page.waitForFunction(() => {
    const joint = window.sphereset.scene().joints.find((j) => j.name === 'j1');
    return joint.value > 0.5;
  }, { timeout: 20000 });
  const q = (await hooks(() => window.sphereset.scene())).joints.find((j) => j.name === 'j1').value;
  await page.waitForFunction((i, want) => {
    const p = window.sphereset.linkWorldPosition(i);
    return p.every((v, n) => Math.abs(v - want[n]) < 1e-6);
  }, { timeout: 20000 }, k, expected(q)).catch(() => {});
  const moved = await hooks((i) => window.sphereset.linkWorldPosition(i), k);
  check(close(moved, expected(q)), `the j1 slider (${q}) moves link2 to ${moved}, expected ${expected(q)}`);

  checkNoErrors(errors, 'in normal use');
});
