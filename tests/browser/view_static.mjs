// `sphereset view MESH SPHERES --html OUT.html`: the page opened from the file, with no server,
// shows the spheres and the certificate as written, refuses edits, and logs no errors. The same
// for the page `sphereset robot -o ROBOT.html` writes beside its fit, whose joint sliders pose
// the robot as the server would, and for a tree's page, whose level slider switches levels
// (neither is an edit).
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { writeBox, writeBoxSpheres, writeRobot } from './fixtures.mjs';
import {
  canvasShot, check, checkNoErrors, openPage, pageStatus, pixelStats, runCli, runTest, startView,
} from './harness.mjs';

await runTest(async (args, browser) => {
  const mesh = writeBox(args.work);
  const spheres = writeBoxSpheres(args.work);
  const html = join(args.work, 'box_static.html');
  runCli(args, ['view', mesh.path, spheres.path, '--html', html]);
  const { page, errors } = await openPage(browser, pathToFileURL(html).href);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);

  check(await hooks(() => window.sphereset.sphereCount(0)) === spheres.count,
    `the static page draws the ${spheres.count} spheres`);
  check((await page.$eval('#mode', (e) => e.textContent)).includes('static snapshot'), 'it says "static snapshot"');
  check(await pageStatus(page) === 'covered', 'its status is the certificate as written: covered');
  check(await hooks(() => window.sphereset.scene()).then((s) => s.solids[0].triangles) === mesh.triangles,
    `the scene has the ${mesh.triangles} triangles`);
  const shot = await pixelStats(browser, await canvasShot(page));
  check(shot.colours > 10, `the picture is not blank (${shot.colours} colours)`);
  const refused = await hooks(() => window.sphereset.setSphere(0, 0, [1, 0, 0, 1]).then(() => null, (e) => e.message));
  check(refused && refused.includes('static snapshot'), `edits are refused (${refused})`);
  checkNoErrors(errors, 'on the static page');

  // The robot's fit, written as a page: every link with its spheres, covered as the fit guarantees.
  const robot = writeRobot(args.work);
  const robotHtml = join(args.work, 'two_link_fit.html');
  runCli(args, ['robot', robot.urdf, '-o', robotHtml, '--default-link-spheres', '4']);
  const fitted = await openPage(browser, pathToFileURL(robotHtml).href);
  const scene = await fitted.page.evaluate(() => window.sphereset.scene());
  check(scene.kind === 'robot' && scene.solids.length === 3, 'sphereset robot -o .html: a robot of three solids');
  for (let k = 0; k < scene.solids.length; k++) {
    const drawn = await fitted.page.evaluate((i) => window.sphereset.sphereCount(i), k);
    check(drawn === scene.solids[k].spheres.length && drawn > 0, `${scene.solids[k].link}: ${drawn} spheres drawn`);
  }
  check(await pageStatus(fitted.page) === 'covered', 'the fitted robot is covered');
  const robotShot = await pixelStats(browser, await canvasShot(fitted.page));
  check(robotShot.colours > 10, `the robot's picture is not blank (${robotShot.colours} colours)`);

  // Its joint slider, clicked near its upper end, poses the robot in the page: every link where
  // the server (the library's kinematics) puts it for the same joint value.
  await fitted.page.$eval('input[data-joint="joint1"]', (e) => e.scrollIntoView());
  const slider = await (await fitted.page.$('input[data-joint="joint1"]')).boundingBox();
  check(!(await fitted.page.$eval('input[data-joint="joint1"]', (e) => e.disabled)), 'the static robot\'s slider is enabled');
  await fitted.page.mouse.click(slider.x + slider.width * 0.85, slider.y + slider.height / 2);
  await fitted.page.waitForFunction(() => window.sphereset.scene().joints[0].value !== 0, { timeout: 20000 });
  const posed = await fitted.page.evaluate(() => ({
    value: window.sphereset.scene().joints[0].value,
    at: window.sphereset.scene().solids.map((_, k) => window.sphereset.linkWorldPosition(k)),
  }));
  const fitYml = join(args.work, 'two_link_fit.yml');
  runCli(args, ['robot', robot.urdf, '-o', fitYml, '--default-link-spheres', '4']);
  const live = await openPage(browser, (await startView(args, [robot.urdf, fitYml])).url);
  await live.page.evaluate((v) => window.sphereset.setJoint('joint1', v), posed.value);
  const served = await live.page.evaluate(() => window.sphereset.scene().solids.map((_, k) => window.sphereset.linkWorldPosition(k)));
  const agree = posed.at.every((p, k) => p.every((v, j) => Math.abs(v - served[k][j]) < 1e-9));
  check(posed.value > 0.5 && agree,
    `the slider (joint1 = ${posed.value}) poses every link where the server does (${JSON.stringify(posed.at)})`);
  check(!(await fitted.page.$eval('#message', (e) => e.classList.contains('error'))), 'posing shows no error');
  checkNoErrors(fitted.errors, "on the robot's page");
  checkNoErrors(live.errors, "on the robot's live page");

  // A tree's page: the level slider, clicked at its left end, shows the root's one sphere with
  // that level's certificate; at its right end, the leaves again.
  const tree = join(args.work, 'box_tree.sph');
  runCli(args, ['tree', mesh.path, '-o', tree, '--branch', '4', '--depth', '2', '--quality', 'fast', '-q']);
  const treeHtml = join(args.work, 'box_tree.html');
  runCli(args, ['view', mesh.path, tree, '--html', treeHtml]);
  const treePage = await openPage(browser, pathToFileURL(treeHtml).href);
  const leaves = await treePage.page.evaluate(() => window.sphereset.sphereCount(0));
  await treePage.page.$eval('#level', (e) => e.scrollIntoView());
  const level = await (await treePage.page.$('#level')).boundingBox();
  await treePage.page.mouse.click(level.x + 2, level.y + level.height / 2);
  await treePage.page.waitForFunction(() => window.sphereset.sphereCount(0) === 1, { timeout: 20000 });
  const root = await treePage.page.evaluate(() => window.sphereset.scene().solids[0]);
  check(root.levels.current === 0 && root.certificate.spheres === 1,
    `the level slider shows the root: ${root.spheres.length} sphere, level ${root.levels.current}, its certificate`);
  check(await treePage.page.$eval('#level-value', (e) => e.textContent) === '0 of 2', 'the level reads "0 of 2"');
  await treePage.page.mouse.click(level.x + level.width - 2, level.y + level.height / 2);
  await treePage.page.waitForFunction((n) => window.sphereset.sphereCount(0) === n, { timeout: 20000 }, leaves);
  check(true, `and back to the ${leaves} leaves`);
  check(!(await treePage.page.$eval('#message', (e) => e.classList.contains('error'))), 'switching levels shows no error');
  checkNoErrors(treePage.errors, "on the tree's page");
});
