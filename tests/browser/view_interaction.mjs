// The page driven by the mouse and keyboard, as a user drives it, against `sphereset view` of a
// box: a click selects a sphere (the panel shows its protrusion bound), Shift + wheel grows its
// radius, Add then a click on the surface adds a sphere of 5% of the diagonal there, the Delete
// key removes the selected sphere, Ctrl+Z brings it back and Ctrl+Y removes it again; every
// change is the server's set afterwards.
import { writeBox, writeBoxSpheres } from './fixtures.mjs';
import { check, checkNoErrors, near, openPage, runTest, startView } from './harness.mjs';

await runTest(async (args, browser) => {
  const mesh = writeBox(args.work);
  const spheres = writeBoxSpheres(args.work);
  const { url } = await startView(args, [mesh.path, spheres.path]);
  const { page, errors } = await openPage(browser, url);
  const serverSet = () => page.evaluate(() => window.sphereset.scene().solids[0].spheres);
  const canvas = await (await page.$('#viewport canvas')).boundingBox();
  const centre = { x: canvas.x + canvas.width / 2, y: canvas.y + canvas.height / 2 };
  const settle = (predicate, ...rest) => page.waitForFunction(predicate, { timeout: 20000 }, ...rest);

  // The middle of the view is inside the spheres: a click there selects one.
  await page.mouse.click(centre.x, centre.y);
  const index = await page.$eval('#sel-index', (e) => Number(e.textContent.replace('#', '')));
  check(await page.$eval('#selection', (e) => !e.classList.contains('hidden')) && index >= 0,
    `a click selects sphere ${index}`);
  // The panel shows that sphere's own certified protrusion bound, the certificate's.
  const shownBound = () => page.$eval('#sel-protrusion', (e) => e.textContent);
  const boundOf = () => page.evaluate((i) => window.sphereset.certificate(0).sphere_protrusion[i], index);
  const bound = await boundOf();
  const largest = await page.evaluate(() => window.sphereset.certificate(0).protrusion);
  check(Number.isFinite(bound) && bound > 0 && bound <= largest,
    `sphere ${index}'s protrusion bound ${bound} is positive and at most the set's ${largest}`);
  check(await shownBound() === `at most ${Number(bound.toPrecision(4))}`,
    `the panel shows it (${await shownBound()})`);

  // Three notches of Shift + wheel: the radius times 1.05^3, sent when the wheel rests (once,
  // or in parts when the notches come slower than the rest).
  const radius = (await serverSet())[index][3];
  const radiusIs = (r) => settle((i, want) => Math.abs(
    window.sphereset.scene().solids[0].spheres[i][3] - want) <= 1e-9 * want, index, r)
    .then(() => true, () => false);
  await page.keyboard.down('Shift');
  for (let i = 0; i < 3; i++) await page.mouse.wheel({ deltaY: -100 });
  await page.keyboard.up('Shift');
  const grown = radius * 1.05 ** 3;
  check(await radiusIs(grown),
    `Shift + wheel: radius ${radius} -> ${(await serverSet())[index][3]}, wanted ${grown}`);
  // Grown, the sphere reaches farther out: the panel follows the new certificate.
  const grownBound = await boundOf();
  check(grownBound > bound && await shownBound() === `at most ${Number(grownBound.toPrecision(4))}`,
    `its protrusion bound grows with it: ${bound} -> ${grownBound}, shown ${await shownBound()}`);

  // A notch after a rest, while the server has not answered the one sent: it starts from the
  // radius sent, so both notches count. The first edit's request is held until the second notch
  // has turned; every request is counted.
  let sentFirst = null;
  const firstSent = new Promise((done) => { sentFirst = done; });
  let letFirstGo = null;
  const secondTurned = new Promise((done) => { letFirstGo = done; });
  let edits = 0;
  const holdFirst = (request) => {
    if (request.isInterceptResolutionHandled()) return;
    const go = () => request.continue().catch(() => {});
    if (!request.url().includes('/api/edit')) return go();
    edits += 1;
    if (edits > 1) return go();
    sentFirst(true);
    return secondTurned.then(go);
  };
  page.on('request', holdFirst);
  await page.setRequestInterception(true);
  await page.keyboard.down('Shift');
  await page.mouse.wheel({ deltaY: 100 });
  const rested = await Promise.race([firstSent, new Promise((done) => setTimeout(done, 20000, false))]);
  await page.mouse.wheel({ deltaY: 100 });
  await page.keyboard.up('Shift');
  letFirstGo();
  const shrunk = grown / 1.05 ** 2;
  check(rested && await radiusIs(shrunk), 'a notch during a slow answer counts: radius ' +
    `${(await serverSet())[index][3]}, wanted ${shrunk}`);
  check(edits === 2, `the two notches, a rest apart, were sent as two edits (${edits})`);
  page.off('request', holdFirst);
  await page.setRequestInterception(false);

  // Add, then a click on the box's surface.
  await page.click('#add');
  await page.mouse.click(centre.x, centre.y);
  await settle((n) => window.sphereset.sphereCount(0) === n, spheres.count + 1);
  const added = (await serverSet())[spheres.count];
  check(near(added[3], 0.05 * mesh.diagonal, 1e-6), `Add: a sphere of radius ${added[3]} (5% of the diagonal)`);
  const onSurface = added.slice(0, 3).some((v, axis) => near(Math.abs(v), [0.5, 0.3, 0.2][axis], 1e-4));
  check(onSurface, `Add: its centre ${added.slice(0, 3)} is on the box's surface`);

  // The new sphere is selected: Delete removes it, Ctrl+Z brings it back, Ctrl+Y removes it.
  await page.keyboard.press('Delete');
  await settle((n) => window.sphereset.sphereCount(0) === n, spheres.count);
  check(true, 'the Delete key removes the selected sphere');
  await page.keyboard.down('Control');
  await page.keyboard.press('z');
  await page.keyboard.up('Control');
  await settle((n) => window.sphereset.sphereCount(0) === n, spheres.count + 1);
  const back = (await serverSet())[spheres.count];
  check(back.every((v, j) => v === added[j]), 'Ctrl+Z brings the same sphere back');
  await page.keyboard.down('Control');
  await page.keyboard.press('y');
  await page.keyboard.up('Control');
  await settle((n) => window.sphereset.sphereCount(0) === n, spheres.count);
  check(true, 'Ctrl+Y removes it again');

  // The radius field of the selection panel.
  await page.mouse.click(centre.x, centre.y);
  const selected = await page.$eval('#sel-index', (e) => Number(e.textContent.replace('#', '')));
  await page.$eval('#sel-r', (input) => {
    input.value = '0.7';
    input.dispatchEvent(new Event('change', { bubbles: true }));
  });
  await settle((i) => window.sphereset.scene().solids[0].spheres[i][3] === 0.7, selected);
  check(true, `the radius field sets sphere ${selected}'s radius`);

  // A notch, then Delete before the wheel rests: the notch is sent first, to the sphere it
  // turned, so Ctrl+Z brings that sphere back grown and no other sphere changed.
  const kept = await serverSet();
  await page.keyboard.down('Shift');
  await page.mouse.wheel({ deltaY: -100 });
  await page.keyboard.up('Shift');
  await page.keyboard.press('Delete');
  await settle((n) => window.sphereset.sphereCount(0) === n, kept.length - 1);
  await new Promise((done) => setTimeout(done, 600));  // past the wheel's rest (300 ms)
  await page.keyboard.down('Control');
  await page.keyboard.press('z');
  await page.keyboard.up('Control');
  await settle((n) => window.sphereset.sphereCount(0) === n, kept.length);
  const restored = await serverSet();
  const grownOnly = restored.every((sphere, i) => sphere.every((v, j) =>
    (i === selected && j === 3 ? near(v, kept[i][3] * 1.05, 1e-12) : v === kept[i][j])));
  check(grownOnly, `a notch then Delete: the notch went to sphere ${selected} before it was deleted`);
  checkNoErrors(errors, 'while using the mouse and keys');
});
