// The link list and the visibility controls, by mouse and keyboard, on the three-link test robot:
// each link with its count, E_r and coverage mark; the filter; a click on a link shows and frames
// it, a click on a sphere selects it; a link's box hides it (its spheres can no longer be
// picked); the mesh, spheres, wireframe and opacity controls; "Frame the gaps" flies to the
// largest uncovered patch. Then a repaired mesh (a cube with one triangle flipped): its surface
// choice shows the repaired solid instead of the original triangles.
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { writeRobot } from './fixtures.mjs';
import { canvasShot, check, checkNoErrors, openPage, pixelStats, runTest, startView } from './harness.mjs';

await runTest(async (args, browser) => {
  const robot = writeRobot(args.work);
  const { url } = await startView(args, [robot.urdf, robot.spheres]);
  const { page, errors } = await openPage(browser, url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);
  const links = (await hooks(() => window.sphereset.scene())).solids.map((s) => s.link);
  const listed = () => page.$$eval('#link-list .link', (rows) => rows.map((r) => r.textContent));
  const rowOf = async (name) => {
    const rows = await page.$$('#link-list .link');
    for (const row of rows) if ((await row.evaluate((r) => r.querySelector('.name').textContent)) === name) return row;
    return null;
  };

  const rows = await listed();
  check(rows.length === 3 && links.every((l, k) => rows[k].includes(l)), `the list has the three links (${rows.join(' | ')})`);
  check(rows.every((r) => r.includes('✓')), 'each marked covered');
  check(rows[links.indexOf('link1')].includes('2 ·'), 'link1 lists its 2 spheres');

  // The filter, typed.
  await page.click('#filter');
  await page.keyboard.type('Link1');
  const filtered = await listed();
  check(filtered.length === 1 && filtered[0].startsWith('link1'), `"Link1" keeps link1 alone (${filtered.join(' | ')})`);
  for (let i = 0; i < 5; i++) await page.keyboard.press('Backspace');
  check((await listed()).length === 3, 'an empty filter lists every link again');

  // A click on link2 shows its certificate and frames it: the camera looks at link2's middle.
  await (await rowOf('link2')).click();
  const k2 = links.indexOf('link2');
  const shownName = await page.$eval('#certificate tr td:nth-child(2)', (e) => e.textContent);
  check(shownName === 'link2', `a click on link2 shows its certificate (${shownName})`);
  const target = await hooks(() => window.sphereset.cameraTarget());
  const link2 = await hooks((k) => window.sphereset.linkWorldPosition(k), k2);
  const offset = Math.hypot(target[0] - link2[0] - 0.1, target[1] - link2[1], target[2] - link2[2]);
  check(offset < 0.1, `and frames it: the camera looks ${offset.toFixed(3)} from link2's box`);
  // Its sphere's row selects it.
  await page.click('#link-list .sphere[data-index="0"]');
  const selected = await hooks(() => window.sphereset.selection());
  check(selected && selected.link === 'link2' && selected.index === 0, `a sphere row selects it (${JSON.stringify(selected)})`);
  await page.keyboard.press('Escape');

  // link1 hidden by its box: drawn no more, and a click where its sphere was picks nothing of it.
  await page.click('#frame');
  const k1 = links.indexOf('link1');
  const at = await hooks((k) => window.sphereset.screenOf(k, window.sphereset.scene().solids[k].spheres[1]), k1);
  await (await rowOf('link1')).$eval('input', (box) => box.scrollIntoView());
  await (await (await rowOf('link1')).$('input')).click();
  check((await hooks(() => window.sphereset.visibility())).solids[k1].shown === false, 'link1\'s box hides it');
  await page.mouse.click(at.x, at.y);
  const picked = await hooks(() => window.sphereset.selection());
  check(!picked || picked.link !== 'link1', `a click where link1's sphere was does not pick it (${JSON.stringify(picked)})`);
  await (await (await rowOf('link1')).$('input')).click();
  check((await hooks(() => window.sphereset.visibility())).solids[k1].shown === true, 'and shows it again');
  await page.keyboard.press('Escape');

  // The mesh, spheres, wireframe and opacity controls change what is drawn.
  const plain = await canvasShot(page);
  await page.click('#show-spheres');
  const noSpheres = await canvasShot(page);
  check((await hooks(() => window.sphereset.visibility())).solids.every((s) => !s.spheres), 'spheres off: none drawn');
  check((await pixelStats(browser, plain, noSpheres)).differing > 1000, 'and the picture changes');
  await page.mouse.click(at.x, at.y);
  check(await hooks(() => window.sphereset.selection()) === null, 'and a click picks no sphere');
  await page.click('#show-spheres');
  await page.click('#show-mesh');
  check((await hooks(() => window.sphereset.visibility())).solids.every((s) => !s.mesh), 'mesh off: no surface drawn');
  await page.click('#show-mesh');
  await page.click('#wireframe');
  check((await hooks(() => window.sphereset.visibility())).solids.every((s) => s.wireframe), 'wireframe on');
  check((await pixelStats(browser, plain, await canvasShot(page))).differing > 100, 'the wireframe changes the picture');
  await page.click('#wireframe');
  const opacity = await (await page.$('#opacity')).boundingBox();
  await page.mouse.click(opacity.x + opacity.width - 3, opacity.y + opacity.height / 2);
  const opaque = (await hooks(() => window.sphereset.visibility())).solids[0].opacity;
  check(opaque > 0.9, `the opacity slider at its right end: opacity ${opaque}`);

  // Gaps: link1's spheres shrunk leave link1 uncovered; "Frame the gaps" looks at link1.
  await hooks((k) => window.sphereset.setSphere(k, 1, [0, 0, 0.3, 0.05]), k1);
  check(await hooks((k) => window.sphereset.redTriangles(k), k1) > 0, 'a shrunk sphere leaves gaps on link1');
  await page.click('#frame');
  await page.click('#frame-gaps');
  const gapTarget = await hooks(() => window.sphereset.cameraTarget());
  const link1 = await hooks((k) => window.sphereset.linkWorldPosition(k), k1);
  check(Math.abs(gapTarget[2] - link1[2]) > 0.2 && Math.abs(gapTarget[2] - link1[2]) < 0.45,
    `"Frame the gaps" looks at the uncovered upper part of link1 (target z ${gapTarget[2].toFixed(3)})`);
  checkNoErrors(errors, 'with the list and the visibility controls');

  // A repaired mesh: the surface choice shows the repaired solid.
  const cube = join(args.work, 'flipped.off');
  writeFileSync(cube, 'OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n3 0 2 3\n3 0 3 1\n' +
    '3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 4 5\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n');
  const ball = join(args.work, 'ball.txt');
  writeFileSync(ball, '0.5 0.5 0.5 0.9\n');
  const repaired = await openPage(browser, (await startView(args, [cube, ball])).url);
  check(await repaired.page.$eval('#surface-row', (e) => !e.classList.contains('hidden')), 'a repaired mesh offers its two surfaces');
  await repaired.page.focus('#surface');
  await repaired.page.keyboard.press('ArrowDown');
  await repaired.page.waitForFunction(() => window.sphereset.visibility().solids[0].repaired === true, { timeout: 20000 });
  const v = await repaired.page.evaluate(() => window.sphereset.visibility());
  check(v.solids[0].repaired === true && v.solids[0].mesh === false, 'the repaired solid is drawn instead of the original triangles');
  checkNoErrors(repaired.errors, 'with a repaired mesh');
});
