// `sphereset view MESH SPHERES --html OUT.html`: the page opened from the file, with no server,
// shows the spheres and the certificate as written, refuses edits, and logs no errors. The same
// for the page `sphereset robot -o ROBOT.html` writes beside its fit.
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { writeBox, writeBoxSpheres, writeRobot } from './fixtures.mjs';
import {
  canvasShot, check, checkNoErrors, openPage, pageStatus, pixelStats, runCli, runTest,
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
  checkNoErrors(fitted.errors, "on the robot's page");
});
