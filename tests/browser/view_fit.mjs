// Fitting from the page, by mouse and keyboard: the box's sphere count typed, the quality chosen,
// Fit: the set becomes the fit (covered, as many spheres as asked), Ctrl+Z gives the old set
// back; a long fit shows its progress bar and Cancel stops it with nothing changed; on the test
// robot, a budget typed and "Fit the robot" fits every link within it and names the split, and one
// Ctrl+Z gives every link its old set back (one Ctrl+Y fits them again). A max protrusion typed
// instead of a count fits the fewest spheres within it (a bad one is refused in the server's
// words), and the robot's links each get their fewest within it.
import { writeBox, writeBoxSpheres, writeRobot } from './fixtures.mjs';
import { check, checkNoErrors, openPage, pageStatus, runTest, startView } from './harness.mjs';

async function pressCtrl(page, key) {
  await page.keyboard.down('Control');
  await page.keyboard.press(key);
  await page.keyboard.up('Control');
}

async function typeInto(page, selector, text) {
  await page.$eval(selector, (e) => e.scrollIntoView());
  await page.click(selector, { clickCount: 3 });
  await page.keyboard.type(text);
}

await runTest(async (args, browser) => {
  const mesh = writeBox(args.work);
  const spheres = writeBoxSpheres(args.work);
  const { page, errors } = await openPage(browser, (await startView(args, [mesh.path, spheres.path])).url);
  const set = () => page.evaluate(() => window.sphereset.scene().solids[0].spheres);
  const before = await set();
  const same = (a, b) => a.length === b.length && a.every((s, i) => s.every((v, j) => v === b[i][j]));

  await typeInto(page, '#fit-spheres', '6');
  await page.focus('#fit-quality');
  await page.keyboard.press('ArrowUp');  // default -> fast
  check(await page.$eval('#fit-quality', (e) => e.value) === 'fast', 'the quality list, by keys: fast');
  await page.click('#fit');
  await page.waitForFunction(() => window.sphereset.sphereCount(0) === 6, { timeout: 60000 });
  check(await pageStatus(page) === 'covered', 'Fit: six spheres that cover the box');
  check((await page.$eval('#message', (e) => e.textContent)).includes('fitted 6 spheres'), 'the message says what was fitted');
  await page.waitForFunction(() => document.getElementById('fit-progress').classList.contains('hidden'), { timeout: 20000 });
  await page.mouse.click(5, 5);  // the keys go to the page, not a field
  await page.keyboard.down('Control');
  await page.keyboard.press('z');
  await page.keyboard.up('Control');
  await page.waitForFunction((n) => window.sphereset.sphereCount(0) === n, { timeout: 20000 }, before.length);
  const back = await set();
  check(back.every((s, i) => s.every((v, j) => v === before[i][j])), 'Ctrl+Z gives the old set back exactly');

  // A long fit: its bar shows how far it is; Cancel stops it and nothing changes.
  await typeInto(page, '#fit-spheres', '400');
  await page.focus('#fit-quality');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowDown');  // fast -> best
  await page.click('#fit');
  await page.waitForFunction(() => !document.getElementById('fit-progress').classList.contains('hidden'), { timeout: 20000 });
  await page.waitForFunction(() => document.getElementById('fit-stage').textContent !== 'starting', { timeout: 20000 });
  const stage = await page.$eval('#fit-stage', (e) => e.textContent);
  check(stage.length > 0, `the progress bar shows the fit's stage (${stage})`);
  await page.click('#fit-cancel');
  await page.waitForFunction(() => document.getElementById('fit-progress').classList.contains('hidden'), { timeout: 60000 });
  check((await page.$eval('#message', (e) => e.textContent)).includes('cancelled'), 'Cancel: "fit cancelled"');
  const after = await set();
  check(after.length === before.length && after.every((s, i) => s.every((v, j) => v === before[i][j])),
    'and the set is as it was');
  // A max protrusion typed instead of a count: the fewest spheres within it, the count named.
  await page.focus('#fit-quality');
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('ArrowUp');  // best -> fast
  await typeInto(page, '#fit-tolerance', '-1');
  await page.click('#fit');
  await page.waitForFunction(() => document.getElementById('message').textContent.includes("max_protrusion '-1'"), { timeout: 20000 });
  check((await set()).length === before.length, 'a bad max protrusion: the server refuses it, the set stays');
  await typeInto(page, '#fit-tolerance', '20%');
  await page.click('#fit');
  await page.waitForFunction(() => document.getElementById('message').textContent.startsWith('max protrusion 20% met: '), { timeout: 60000 });
  const found = await page.$eval('#message', (e) => e.textContent);
  const count = Number(/met: (\d+) spheres/.exec(found)[1]);
  await page.waitForFunction((n) => window.sphereset.sphereCount(0) === n, { timeout: 20000 }, count);
  check(count >= 1 && (await set()).length === count, `the count found is the set shown (${found})`);
  check(await pageStatus(page) === 'covered', 'the tolerance fit covers the box');
  const cert = await page.evaluate(() => window.sphereset.certificate(0));
  check(Number.isFinite(cert.protrusion) && cert.protrusion > 0, `its certificate has a protrusion (${cert.protrusion})`);
  await page.mouse.click(5, 5);
  await pressCtrl(page, 'z');
  await page.waitForFunction((n) => window.sphereset.sphereCount(0) === n, { timeout: 20000 }, before.length);
  check(same(await set(), before), 'Ctrl+Z undoes the tolerance fit');
  await typeInto(page, '#fit-tolerance', '');
  await page.keyboard.press('Backspace');
  check(await page.$eval('#fit-tolerance', (e) => e.value) === '', 'the field cleared: counts again');
  const refusals = errors.filter((e) => e.includes('status of 400'));
  check(refusals.length === 1, `the browser logs the one refused request (${refusals.length})`);
  checkNoErrors(errors.filter((e) => !e.includes('status of 400')), 'while fitting the box');

  // The robot's budget.
  const robot = writeRobot(args.work);
  const live = await openPage(browser, (await startView(args, [robot.urdf, robot.spheres])).url);
  const sets = () => live.page.evaluate(() => window.sphereset.scene().solids.map((s) => s.spheres));
  const sameSets = (a, b) => a.length === b.length && a.every((one, k) => same(one, b[k]));
  // Until the links hold `want` exactly (JSON keeps every digit of a double).
  const waitForSets = (want) => live.page.waitForFunction(
    (w) => JSON.stringify(window.sphereset.scene().solids.map((s) => s.spheres)) === w,
    { timeout: 20000 }, JSON.stringify(want));
  const robotBefore = await sets();
  await typeInto(live.page, '#fit-budget', '7');
  await live.page.focus('#fit-quality');
  await live.page.keyboard.press('ArrowUp');
  await live.page.click('#fit-robot');
  await live.page.waitForFunction(() => document.getElementById('message').textContent.startsWith('budget 7'), { timeout: 120000 });
  const scene = await live.page.evaluate(() => window.sphereset.scene());
  const total = scene.solids.reduce((n, s) => n + s.spheres.length, 0);
  check(total <= 7 && total >= scene.solids.length, `"Fit the robot" with a budget of 7: ${total} spheres over the links`);
  const message = await live.page.$eval('#message', (e) => e.textContent);
  check(scene.solids.every((s) => message.includes(`${s.link} ${s.spheres.length}`)), `the split is named per link (${message})`);
  check(await pageStatus(live.page) === 'covered', 'every link covered');
  const fitted = await sets();
  check(!sameSets(fitted, robotBefore), 'the fit changed the links');
  await live.page.mouse.click(5, 5);
  await pressCtrl(live.page, 'z');
  await waitForSets(robotBefore);
  check(sameSets(await sets(), robotBefore), "one Ctrl+Z gives every link its set from before the robot's fit");
  await pressCtrl(live.page, 'z');  // nothing left: the page says so, the sets stay
  await live.page.waitForFunction(() => document.getElementById('message').textContent === 'nothing to undo', { timeout: 20000 });
  check(sameSets(await sets(), robotBefore), 'a second Ctrl+Z has nothing left to undo');
  await pressCtrl(live.page, 'y');
  await waitForSets(fitted);
  check(sameSets(await sets(), fitted), 'one Ctrl+Y fits every link again');
  // A max protrusion and no budget: each link its fewest spheres within 30 % of its diagonal.
  await typeInto(live.page, '#fit-budget', '');
  await live.page.keyboard.press('Backspace');
  await typeInto(live.page, '#fit-tolerance', '30%');
  await live.page.click('#fit-robot');
  await live.page.waitForFunction(() => document.getElementById('message').textContent.startsWith('max protrusion 30% met: '), { timeout: 120000 });
  const limited = await live.page.evaluate(() => window.sphereset.scene());
  const said = await live.page.$eval('#message', (e) => e.textContent);
  check(limited.solids.every((s) => said.includes(`${s.link} ${s.spheres.length}`)), `each link's count is named (${said})`);
  check(await pageStatus(live.page) === 'covered', 'every link covered within its limit');
  checkNoErrors(live.errors, "while fitting the robot's budget");
});
