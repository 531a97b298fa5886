// `sphereset view` on the bundled spot (examples/spot.obj, 5856 triangles) with 16 spheres the
// command fits first: the page draws them, covered; the three largest shrunk by a quarter leave
// gaps that the page draws in red as the certificate lists them; the Bound button covers again,
// and `sphereset eval` of what the Save button wrote agrees with the page's figures.
import { join } from 'node:path';
import {
  canvasShot, check, checkNoErrors, near, openPage, pageStatus, pixelStats, runCli, runTest,
  startView,
} from './harness.mjs';

const spot = new URL('../../examples/spot.obj', import.meta.url).pathname;

await runTest(async (args, browser) => {
  const fitted = join(args.work, 'spot_16.json');
  const saved = join(args.work, 'spot_edited.json');
  runCli(args, ['fit', spot, '-n', '16', '--quality', 'fast', '-o', fitted, '-q']);
  const { url } = await startView(args, [spot, fitted, '--output', saved]);
  const { page, errors } = await openPage(browser, url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);

  const scene = await hooks(() => window.sphereset.scene());
  check(scene.solids[0].triangles === 5856, `spot's ${scene.solids[0].triangles} triangles`);
  check(await hooks(() => window.sphereset.sphereCount(0)) === 16, 'the page draws the 16 spheres');
  check(await pageStatus(page) === 'covered', 'the fitted set is covered');
  const before = await canvasShot(page);
  check((await pixelStats(browser, before)).colours > 10, 'the picture is not blank');

  await hooks(async () => {
    const set = window.sphereset.scene().solids[0].spheres;
    const largest = set.map((s, i) => [s[3], i]).sort((a, b) => b[0] - a[0]).slice(0, 3);
    for (const [, k] of largest) {
      const s = set[k];
      await window.sphereset.setSphere(0, k, [s[0], s[1], s[2], 0.75 * s[3]]);
    }
  });
  check(await pageStatus(page) === 'not covered', 'three spheres shrunk by hand: not covered');
  const red = await hooks(() => window.sphereset.redTriangles(0));
  const listed = new Set((await hooks(() => window.sphereset.certificate(0))).uncovered_triangles).size;
  check(red > 0 && red === listed, `${red} red triangles, as the certificate lists (${listed})`);
  const after = await canvasShot(page);
  check((await pixelStats(browser, before, after)).differing > 100, 'the picture changes');

  // The page's own buttons: Bound, then Save.
  const version = async () => (await hooks(() => window.sphereset.scene())).version;
  const waitForVersion = (v) => page.waitForFunction((n) => window.sphereset.scene().version > n,
    { timeout: 60000 }, v);
  const beforeBound = await version();
  await page.click('#bound');
  await waitForVersion(beforeBound);
  check(await pageStatus(page) === 'covered', 'the Bound button: covered again');
  check(await hooks(() => window.sphereset.redTriangles(0)) === 0, 'Bound: no red triangles');
  await page.click('#save');
  await page.waitForFunction(() => /saved /.test(document.getElementById('message').textContent),
    { timeout: 60000 });
  check(true, 'the Save button: saved');
  const pageEr = (await hooks(() => window.sphereset.certificate(0))).er_sum;
  const evaluated = JSON.parse(runCli(args, ['eval', spot, saved, '--json']));
  check(near(evaluated.er_sum, pageEr, 1e-9), `eval's E_r ${evaluated.er_sum}, the page's ${pageEr}`);
  check(evaluated.surface_covered && evaluated.interior_covered, 'eval: the saved set covers');
  checkNoErrors(errors, 'on spot');
});
