// The page alone, without the command: the built page (web/) given a synthetic scene where its
// data marker stands, as `sphereset view --html` does (docs/view.md), and opened from the disk.
// The scene's certificate names ten uncovered triangles; the page must draw exactly those red,
// say "not covered", select a sphere on a click and log no errors.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { boxMesh } from './fixtures.mjs';
import { canvasShot, check, checkNoErrors, openPage, pageStatus, pixelStats, runTest } from './harness.mjs';

// docs/view.md: uint32 V, uint32 T, float32 xyz x V, uint32 abc x T, little-endian.
function geometryBase64({ vertices, triangles }) {
  const buffer = Buffer.alloc(8 + 12 * vertices.length + 12 * triangles.length);
  buffer.writeUInt32LE(vertices.length, 0);
  buffer.writeUInt32LE(triangles.length, 4);
  let at = 8;
  for (const p of vertices) for (const v of p) at = buffer.writeFloatLE(v, at);
  for (const t of triangles) for (const v of t) at = buffer.writeUInt32LE(v, at);
  return buffer.toString('base64');
}

function staticScene(mesh) {
  const spheres = [[-0.25, 0, 0, 0.45], [0.25, 0, 0, 0.3]];
  const uncovered = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9];
  return {
    kind: 'mesh', title: 'box', version: 1,
    solids: [{
      name: 'box', link: null, triangles: mesh.triangles.length, vertices: mesh.vertices.length,
      bounds: [mesh.half.map((h) => -h), mesh.half], diagonal: mesh.diagonal, spheres, levels: null,
      certificate: {
        spheres: 2, er_sum: 0.5, outside_volume: [0.1, 0.02], volume: 0.24,
        surface_covered: false, interior_covered: true, original_covered: false, covered: false,
        max_gap: 0.01, uncovered_triangles: uncovered, seconds: 0.001,
      },
      geometry: geometryBase64(mesh),
    }],
    joints: [],
    poses: [[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]],
    save: { path: '/nowhere/box.txt', format: 'text' },
  };
}

await runTest(async (args, browser) => {
  if (!args.page) throw new Error('--page PAGE.html is required');
  const mesh = boxMesh();
  const scene = staticScene(mesh);
  const data = JSON.stringify(scene).replace(/</g, '\\u003c');
  const html = readFileSync(args.page, 'utf8').replace('<!--SPHERESET_DATA-->',
    () => `<script id="sphereset-data" type="application/json">${data}</script>`);
  const file = join(args.work, 'fixture.html');
  writeFileSync(file, html);
  const { page, errors } = await openPage(browser, pathToFileURL(file).href);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);

  check(await hooks(() => window.sphereset.sphereCount(0)) === 2, 'two spheres drawn');
  check(await hooks(() => window.sphereset.redTriangles(0)) === 10, 'the ten uncovered triangles drawn red');
  check(await pageStatus(page) === 'not covered', 'status "not covered"');
  check((await page.$eval('#mode', (e) => e.textContent)).includes('static snapshot'), 'it says "static snapshot"');
  check((await hooks(() => window.sphereset.certificate(0))).er_sum === 0.5, 'certificate(0) is the scene\'s');
  check(!(await hooks(() => window.sphereset.scene())).solids[0].geometry, 'scene() leaves the geometry out');
  const origin = await hooks(() => window.sphereset.linkWorldPosition(0));
  check(origin.every((v) => v === 0), 'the solid sits at its identity pose');
  const shot = await pixelStats(browser, await canvasShot(page));
  check(shot.colours > 10, `the picture is not blank (${shot.colours} colours)`);

  // A click in the middle of the view lands on a sphere: the selection panel shows it.
  const box = await (await page.$('#viewport canvas')).boundingBox();
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  const selected = await page.$eval('#selection', (e) => !e.classList.contains('hidden'));
  check(selected, 'a click on a sphere selects it');
  const refused = await hooks(() => window.sphereset.bound(0).then(() => null, (e) => e.message));
  check(refused && refused.includes('static snapshot'), `Bound is refused on a static page (${refused})`);
  checkNoErrors(errors, 'on the page');
});
