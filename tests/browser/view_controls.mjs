// The page's controls and its listed defects, driven by the mouse and keyboard against
// `sphereset view` of a box: a typed radius leaves the centre as the set holds it (not as its
// field rounds it), Shift + wheel lights no handle of the gizmo nor the pointer on the centre its
// free-move handle, the colours are each sphere's fraction outside (a sphere off the solid stays
// red whatever the others do) unless the relative scale is chosen, the gaps are drawn in their
// own colour on top of the spheres, the fields and buttons fit the panel, "?" shows the mouse and
// keys, and PNG saves the page's state.
import { readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { writeBox } from './fixtures.mjs';
import {
  canvasShot, check, checkNoErrors, countPixels, near, openPage, runTest, startView,
} from './harness.mjs';

const magenta = 'r > 180 && b > 180 && g < 90';

await runTest(async (args, browser) => {
  const mesh = writeBox(args.work);
  // A centre with more digits than a field shows.
  const spheresPath = join(args.work, 'box_digits.txt');
  const centre = [0.00020777180686787163, 0.013333333333333334, -0.0071428571428571435];
  writeFileSync(spheresPath, `${centre.join(' ')} 0.65\n0.3 0 0 0.2\n-0.3 0 0 0.2\n`);
  const { url } = await startView(args, [mesh.path, spheresPath]);
  const { page, errors } = await openPage(browser, url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);
  const serverSet = () => hooks(() => window.sphereset.scene().solids[0].spheres);
  const settle = (predicate, ...rest) => page.waitForFunction(predicate, { timeout: 20000 }, ...rest);
  const canvas = await (await page.$('#viewport canvas')).boundingBox();
  const middle = { x: canvas.x + canvas.width / 2, y: canvas.y + canvas.height / 2 };

  // The fields and buttons fit the panel.
  await page.mouse.click(middle.x, middle.y);
  const selected = await hooks(() => window.sphereset.selection());
  check(selected !== null, `a click selects sphere ${selected && selected.index}`);
  const clipped = await page.$$eval('#selection input[type=number]',
    (inputs) => inputs.filter((i) => i.scrollWidth > i.clientWidth + 1).map((i) => `${i.id}: ${i.value}`));
  check(clipped.length === 0, `no selection field clips its value (${clipped.join(', ')})`);
  const rows = await page.$$eval('#edit-tools button', (buttons) => new Set(buttons.map((b) => b.offsetTop)).size);
  check(rows === 1, `the edit buttons (Redo included) stand on one line (${rows} lines)`);

  // Shift + wheel over the selected sphere's centre: the radius changes, no gizmo handle lights.
  await page.keyboard.down('Shift');
  await page.mouse.wheel({ deltaY: -100 });
  await page.keyboard.up('Shift');
  check(await hooks(() => window.sphereset.gizmoAxis()) === null, 'Shift + wheel lights no handle of the gizmo');
  const grownFrom = await hooks((i) => window.sphereset.scene().solids[0].spheres[i][3], selected.index);
  await settle((i, r) => window.sphereset.scene().solids[0].spheres[i][3] !== r, selected.index, grownFrom);

  // The pointer resting on the selected sphere's centre never lights the gizmo's free-move
  // handle (all three coordinates at once: taken out; an arrow seen end-on may light).
  const hub = await hooks((i) => window.sphereset.screenOf(0, window.sphereset.scene().solids[0].spheres[i]),
    selected.index);
  const frames = () => hooks(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  const sphereOf = await hooks((i) => window.sphereset.scene().solids[0].spheres[i], selected.index);
  const along = await hooks((c) => window.sphereset.screenOf(0, [c[0] + 0.01, c[1], c[2]]), sphereOf);
  const norm = Math.hypot(along.x - hub.x, along.y - hub.y);
  let arrow = null;  // the pointer along the x arrow lights it: the hover is read
  for (let t = 8; t < 240 && !arrow; t += 4) {
    const at = { x: hub.x + t * (along.x - hub.x) / norm, y: hub.y + t * (along.y - hub.y) / norm };
    await page.mouse.move(at.x, at.y);
    await frames();
    if (await hooks(() => window.sphereset.gizmoAxis()) === 'X') arrow = at;
  }
  check(arrow !== null, 'the pointer along the x arrow lights it');
  await page.mouse.move(hub.x + 3, hub.y + 3);
  await page.mouse.move(hub.x, hub.y);
  await frames();
  const lit = await hooks(() => window.sphereset.gizmoAxis());
  check(lit !== 'XYZ', `the pointer on the selected centre lights no free-move handle (${lit})`);

  // Select the big sphere (index 0) at its centre on the screen and type only its radius.
  const at = await hooks(() => window.sphereset.screenOf(0, window.sphereset.scene().solids[0].spheres[0]));
  await page.keyboard.press('Escape');
  const before = (await serverSet())[0];
  await page.mouse.click(at.x, at.y);
  const big = await hooks(() => window.sphereset.selection());
  if (big && big.index === 0) {
    await page.click('#sel-r', { clickCount: 3 });
    await page.keyboard.type('0.7');
    await page.keyboard.press('Enter');
    await settle(() => window.sphereset.scene().solids[0].spheres[0][3] === 0.7);
    const after = (await serverSet())[0];
    check(after.slice(0, 3).every((v, j) => v === before[j]),
      `typing the radius keeps the centre bit for bit (${after.slice(0, 3)} was ${before.slice(0, 3)})`);
  } else {
    check(false, `a click at the big sphere's centre selects it (got ${JSON.stringify(big)})`);
  }

  // A small sphere typed far off the solid: all of it outside, red on the absolute scale, and
  // still red after the big sphere grows past it in outside volume.
  const small = await hooks(() => window.sphereset.screenOf(0, window.sphereset.scene().solids[0].spheres[1]));
  await page.mouse.click(small.x, small.y);
  const picked = await hooks(() => window.sphereset.selection());
  const index = picked ? picked.index : 1;
  await page.click('#sel-x', { clickCount: 3 });
  await page.keyboard.type('5');
  await page.keyboard.press('Enter');
  await settle((i) => window.sphereset.scene().solids[0].spheres[i][0] === 5, index);
  await hooks(() => window.sphereset.setSphere(0, 0, [0, 0, 0, 1]));
  const red = await hooks((i) => window.sphereset.sphereColor(0, i), index);
  check(red[0] > 0.6 && red[1] < 0.2 && red[2] < 0.2, `a sphere wholly outside is red on the absolute scale (${red})`);
  const bigColour = await hooks(() => window.sphereset.sphereColor(0, 0));
  check(bigColour[1] > red[1] + 0.05, `the big sphere, 94% outside, is further from the top red (${bigColour})`);
  await page.focus('#scale');
  await page.keyboard.press('ArrowDown');
  await settle(() => document.getElementById('legend-what').textContent === 'outside volume');
  const relative = await hooks((i) => window.sphereset.sphereColor(0, i), index);
  check(relative[2] > relative[0] && relative[2] > relative[1],
    `on the relative scale the same sphere is blue beside the big one (${relative})`);
  await page.keyboard.press('ArrowUp');
  await settle(() => document.getElementById('legend-what').textContent === 'fraction outside');

  // Gaps: the big sphere shrunk leaves the box's corners uncovered; they are drawn magenta, a
  // colour on no ramp, over the spheres in front of them.
  await hooks(() => window.sphereset.setSphere(0, 0, [0, 0, 0, 0.45]));
  const gaps = await hooks(() => window.sphereset.redTriangles(0));
  check(gaps > 0, `a shrunk sphere leaves ${gaps} gap triangles`);
  const shot = await countPixels(browser, await canvasShot(page), magenta);
  check(shot.count > 50, `the gaps are drawn in the gap colour (${shot.count} magenta pixels)`);

  // "?" shows the mouse and keys; Escape hides them; so do the button and Close.
  await page.mouse.click(middle.x, canvas.y + 5);
  await page.keyboard.press('?');
  check(await page.$eval('#help', (e) => !e.classList.contains('hidden')), '"?" shows the mouse and keys');
  await page.keyboard.press('Escape');
  check(await page.$eval('#help', (e) => e.classList.contains('hidden')), 'Escape hides them');
  await page.click('#help-button');
  check(await page.$eval('#help', (e) => !e.classList.contains('hidden')), 'the ? button shows them');
  await page.click('#help-close');
  check(await page.$eval('#help', (e) => e.classList.contains('hidden')), 'Close hides them');

  // PNG: the page's state, a band with the title, the status and the legend above the view.
  const downloads = join(args.work, 'downloads');
  const session = await page.createCDPSession();
  await session.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads });
  await page.click('#png');
  let file = null;
  for (let i = 0; i < 100 && !file; i++) {
    await new Promise((r) => setTimeout(r, 100));
    const names = (() => { try { return readdirSync(downloads); } catch { return []; } })();
    file = names.find((n) => n.endsWith('.png'));
  }
  check(file !== null && file !== undefined, `PNG downloads a picture (${file})`);
  if (file) {
    const png = readFileSync(join(downloads, file));
    const band = await countPixels(browser, png, 'r > 245 && g > 205 && g < 220 && b > 205 && b < 220');
    const view = await countPixels(browser, await canvasShot(page), 'true');
    check(band.height > view.height && near(band.width, view.width, 0.01),
      `the picture is the view and a band above it (${band.width}x${band.height}, view ${view.width}x${view.height})`);
    check(band.count > 100, `the band shows the status "not covered" in its colour (${band.count} pixels)`);
  }
  checkNoErrors(errors, 'while using the controls');
});
