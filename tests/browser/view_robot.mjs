// `sphereset view ROBOT.urdf SPHERES.yml` in headless Chromium: one solid per link with its
// spheres, placed by the poses; a joint moves the links after it, through the hook and through
// the page's own slider; a selection names its link and is dropped when another link is shown;
// the robot is framed again when a joint takes it out of the view (a toggle), and a slider keeps
// its width whatever its value's text.
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

  // A click on link1's first sphere selects it and the panel names link1.
  const link1 = links.indexOf('link1');
  const onScreen = await hooks((i) => window.sphereset.screenOf(i, window.sphereset.scene().solids[i].spheres[0]), link1);
  await page.mouse.click(onScreen.x, onScreen.y);
  const selected = await hooks(() => window.sphereset.selection());
  check(selected && selected.link === 'link1', `a click on link1's sphere selects it (${JSON.stringify(selected)})`);
  check(await page.$eval('#sel-link', (e) => e.textContent) === 'link1', 'the selection panel names link1');
  // Another link picked in the list (keyboard): the selection and its gizmo go.
  await page.focus('#solid');
  await page.keyboard.press(links.indexOf('base_link') < link1 ? 'ArrowUp' : 'ArrowDown');
  check(await hooks(() => window.sphereset.selection()) === null, 'picking another link drops the selection');
  check(await page.$eval('#selection', (e) => e.classList.contains('hidden')), 'and hides its panel');

  // Zoomed in until the robot leaves the view, a joint move frames it again.
  const box = await (await page.$('#viewport canvas')).boundingBox();
  const inView = () => hooks(() => window.sphereset.sceneInView());
  const zoomIn = async () => {
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    for (let i = 0; i < 12 && await inView(); i++) await page.mouse.wheel({ deltaY: -400 });
  };
  await zoomIn();
  check(!(await inView()), 'zoomed in, the robot is partly out of view');
  await page.$eval('input[data-joint="joint1"]', (e) => e.scrollIntoView());
  const slider = await (await page.$('input[data-joint="joint1"]')).boundingBox();
  const width = slider.width;
  const value = () => hooks(() => window.sphereset.scene().joints.find((j) => j.name === 'joint1').value);
  const was = await value();
  await page.mouse.click(slider.x + slider.width * 0.9, slider.y + slider.height / 2);
  await page.waitForFunction((v) => window.sphereset.scene().joints[0].value !== v, { timeout: 20000 }, was);
  check(await inView(), `a joint move by the slider (to ${await value()}) frames the robot again`);
  const after = await (await page.$('input[data-joint="joint1"]')).boundingBox();
  check(after.width === width, `the slider keeps its width (${width} -> ${after.width})`);
  // With the toggle off, the camera stays.
  await page.click('#auto-frame');
  await zoomIn();
  await page.$eval('input[data-joint="joint1"]', (e) => e.scrollIntoView());
  const again = await value();
  await page.mouse.click(slider.x + slider.width * 0.2, slider.y + slider.height / 2);
  await page.waitForFunction((v) => window.sphereset.scene().joints[0].value !== v, { timeout: 20000 }, again);
  check(!(await inView()), 'with "frame the robot" off, a joint move leaves the camera where it was');

  checkNoErrors(errors, 'in normal use');
});
