// `sphereset view MESH SPHERES` in headless Chromium: the page shows the set, an edit off the
// surface makes it "not covered" with red triangles, undo and redo, Bound covers again, the saved
// file evaluates (by `sphereset eval`) to the page's E_r, and the picture changes with an edit.
import { join } from 'node:path';
import { writeBox, writeBoxSpheres } from './fixtures.mjs';
import {
  canvasShot, check, checkNoErrors, near, openPage, pageMessage, pageStatus, pixelStats, runCli,
  runTest, startView,
} from './harness.mjs';

await runTest(async (args, browser) => {
  const mesh = writeBox(args.work);
  const spheres = writeBoxSpheres(args.work);
  const saved = join(args.work, 'box_saved.txt');
  const { url } = await startView(args, [mesh.path, spheres.path, '--output', saved]);
  const { page, errors } = await openPage(browser, url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);

  check(await hooks(() => window.sphereset.sphereCount(0)) === spheres.count,
    `the page draws the ${spheres.count} spheres of the file`);
  check((await hooks(() => window.sphereset.scene())).solids[0].spheres.length === spheres.count,
    'scene() holds the set');
  check(await pageStatus(page) === 'covered', 'status "covered" for a set around the box');
  check(await hooks(() => window.sphereset.redTriangles(0)) === 0, 'no red triangles');
  // The token leaves the address bar once the page has read it; every answer forbids sniffing,
  // referrers and framing.
  check(await page.evaluate(() => location.search) === '', 'the token is gone from the address');
  const first = await fetch(url);
  check(first.headers.get('x-content-type-options') === 'nosniff' &&
    first.headers.get('referrer-policy') === 'no-referrer' &&
    first.headers.get('cache-control') === 'no-store', 'the page is sent with its safety headers');

  const before = await canvasShot(page);
  const plain = await pixelStats(browser, before);
  check(plain.colours > 10, `the picture is not blank (${plain.colours} colours)`);

  // The big sphere moved and shrunk over the +x half: the -x end of the box is left bare.
  await hooks(() => window.sphereset.setSphere(0, 0, [0.35, 0, 0, 0.5]));
  check(await pageStatus(page) === 'not covered', 'status "not covered" after moving the big sphere');
  const red = await hooks(() => window.sphereset.redTriangles(0));
  const certificate = await hooks(() => window.sphereset.certificate(0));
  const listed = new Set(certificate.uncovered_triangles).size;
  check(red > 0 && red < mesh.triangles && red === listed,
    `red triangles drawn (${red} of ${mesh.triangles}) as the certificate lists them (${listed})`);
  check(!certificate.covered && !certificate.surface_covered, 'the certificate says not covered');
  const after = await canvasShot(page);
  const changed = await pixelStats(browser, before, after);
  check(changed.differing > 100, `the picture changes with the edit (${changed.differing} pixels)`);

  await hooks(() => window.sphereset.undo());
  check(await pageStatus(page) === 'covered', 'undo: covered again');
  check((await hooks(() => window.sphereset.scene())).solids[0].spheres[0].every((v, j) => v === [0, 0, 0, 0.65][j]),
    'undo: the sphere is back');
  await hooks(() => window.sphereset.redo());
  check(await pageStatus(page) === 'not covered', 'redo: not covered again');

  await hooks(() => window.sphereset.addSphere(0, [0, 0, 0.2, 0.05]));
  check(await hooks(() => window.sphereset.sphereCount(0)) === spheres.count + 1, 'add: one more sphere');
  await hooks(() => window.sphereset.deleteSphere(0, 3));
  check(await hooks(() => window.sphereset.sphereCount(0)) === spheres.count, 'delete: one fewer');

  await hooks(() => window.sphereset.bound(0));
  check(await pageStatus(page) === 'covered', 'Bound: covered');
  check(await hooks(() => window.sphereset.redTriangles(0)) === 0, 'Bound: no red triangles');

  const answer = await hooks(() => window.sphereset.save());
  check(answer.path === saved, `save writes ${saved}`);
  const pageEr = (await hooks(() => window.sphereset.certificate(0))).er_sum;
  const evaluated = JSON.parse(runCli(args, ['eval', mesh.path, saved, '--json']));
  check(near(evaluated.er_sum, pageEr, 1e-6),
    `sphereset eval of the saved file: E_r ${evaluated.er_sum}, the page ${pageEr}`);
  check(evaluated.surface_covered && evaluated.interior_covered, 'sphereset eval: the saved set covers');
  // The certified protrusion: the page's bound (0.01 of the diagonal) and eval's (0.001) hold
  // the same value: each bound is at least the other's witness distance, and it is shown.
  const pageCertificate = await hooks(() => window.sphereset.certificate(0));
  const pageProtrusion = pageCertificate.protrusion;
  check(pageProtrusion >= evaluated.protrusion.witness_distance
    && evaluated.protrusion.bound >= pageProtrusion - 0.011 * evaluated.bbox_diagonal,
  `protrusion: eval ${evaluated.protrusion.witness_distance} to ${evaluated.protrusion.bound}, the page ${pageProtrusion}`);
  const panelRows = await page.$$eval('#certificate tr', (rows) => rows.map((r) => r.textContent));
  const row = panelRows.find((t) => t.startsWith('protrusion'));
  check(row !== undefined && row.includes(String(Number(pageProtrusion.toPrecision(4)))),
    `the panel shows the protrusion (${row})`);

  const message = await pageMessage(page);
  check(!message.error, `no error on the message line (${message.text})`);
  checkNoErrors(errors, 'in normal use');

  // A refused edit: the server's words on the message line, and the set as it was.
  const refused = await hooks(() => window.sphereset.setSphere(0, 0, [0, 0, 0, -1]).then(() => null, (e) => e.message));
  check(refused !== null, `a negative radius is refused (${refused})`);
  const shown = await pageMessage(page);
  check(shown.error && shown.text.length > 0, `the refusal is on the message line (${shown.text})`);
  check(await hooks(() => window.sphereset.sphereCount(0)) === spheres.count, 'the refused edit changed nothing');
});
