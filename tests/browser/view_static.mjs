// `sphereset view MESH SPHERES --html OUT.html`: the page opened from the file, with no server,
// shows the spheres and the certificate as written, refuses edits, and logs no errors.
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { writeBox, writeBoxSpheres } from './fixtures.mjs';
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
});
