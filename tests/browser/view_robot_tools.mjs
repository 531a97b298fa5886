// A robot engineer's tools on the test robot, by mouse and keyboard: with an SRDF that allows
// only base_link–link1, link1 and link2 (overlapping spheres) are listed in contact and drawn;
// a sphere moved off clears the contact; the link under the pointer is named beside it; Save
// writes the robot as a URDF beside the save path when that format is chosen; on a turned link,
// the gizmo's x arrow dragged by the mouse changes the centre's x in the link's frame alone.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { writeRobot } from './fixtures.mjs';
import { check, checkNoErrors, openPage, runTest, startView } from './harness.mjs';

await runTest(async (args, browser) => {
  const robot = writeRobot(args.work);
  const srdf = join(args.work, 'two_link.srdf');
  writeFileSync(srdf, '<robot name="two_link"><disable_collisions link1="base_link" link2="link1" reason="Adjacent"/></robot>\n');
  const { page, errors } = await openPage(browser, (await startView(args, [robot.urdf, robot.spheres, '--srdf', srdf])).url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);
  const links = (await hooks(() => window.sphereset.scene())).solids.map((s) => s.link);

  await page.$eval('#collision-box', (e) => e.scrollIntoView());
  const pairs = await page.$$eval('#contact-list .pair', (rows) => rows.map((r) => r.textContent));
  check(pairs.length === 1 && pairs[0] === 'link1 – link2', `link1 – link2 listed in contact (${pairs.join(', ')})`);
  check((await page.$eval('#allowed-summary', (e) => e.textContent)).includes('1 allowed pairs (from the SRDF)'),
    'the SRDF\'s one pair is listed as allowed');
  check((await hooks(() => window.sphereset.visibility())).contactSegments === 1, 'and the contact is drawn');

  // The link under the pointer, named beside it.
  const k2 = links.indexOf('link2');
  const at = await hooks((k) => window.sphereset.screenOf(k, window.sphereset.scene().solids[k].spheres[0]), k2);
  await page.mouse.move(at.x - 3, at.y - 3);
  await page.mouse.move(at.x, at.y);
  await page.waitForFunction(() => !document.getElementById('hover').classList.contains('hidden'), { timeout: 10000 });
  const named = await page.$eval('#hover', (e) => e.textContent);
  check(named === 'link2', `hovering link2's sphere names it (${named})`);

  // link2's sphere typed far away: no contact any more.
  await page.mouse.click(at.x, at.y);
  const selected = await hooks(() => window.sphereset.selection());
  check(selected && selected.link === 'link2', 'a click selects link2\'s sphere');
  await page.$eval('#sel-x', (e) => e.scrollIntoView());
  await page.click('#sel-x', { clickCount: 3 });
  await page.keyboard.type('5');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.getElementById('contact-summary').textContent.startsWith('no pair'), { timeout: 20000 });
  check((await hooks(() => window.sphereset.visibility())).contactSegments === 0, 'moved off: no contact listed or drawn');

  // Save as URDF, chosen by keys.
  await page.$eval('#save-format', (e) => e.scrollIntoView());
  const formats = await page.$$eval('#save-format option', (o) => o.map((x) => x.value));
  check(formats.includes('yaml') && formats.includes('urdf'), `Save offers the robot formats (${formats.join(', ')})`);
  await page.focus('#save-format');
  await page.keyboard.press('ArrowDown');
  check(await page.$eval('#save-format', (e) => e.value) === 'urdf', 'urdf chosen by keys');
  await page.click('#save');
  await page.waitForFunction(() => document.getElementById('message').textContent.startsWith('saved'), { timeout: 20000 });
  const saved = join(args.work, 'two_link_spheres.urdf');
  const message = await page.$eval('#message', (e) => e.textContent);
  check(message.includes(saved) && existsSync(saved), `Save wrote ${saved} (${message})`);
  if (existsSync(saved)) check(readFileSync(saved, 'utf8').includes('<sphere radius'), 'a URDF with sphere collisions');

  // link1 turned by its joint; its first sphere selected; the gizmo's x arrow found by hovering
  // along the link's own x on the screen, then dragged.
  await hooks(() => window.sphereset.setJoint('joint1', 0.7));
  const k1 = links.indexOf('link1');
  const sphere = await hooks((k) => window.sphereset.scene().solids[k].spheres[0], k1);
  const centre = await hooks((k, c) => window.sphereset.screenOf(k, c), k1, sphere.slice(0, 3));
  const along = await hooks((k, c) => window.sphereset.screenOf(k, [c[0] + 0.01, c[1], c[2]]), k1, sphere.slice(0, 3));
  const norm = Math.hypot(along.x - centre.x, along.y - centre.y);
  const d = { x: (along.x - centre.x) / norm, y: (along.y - centre.y) / norm };
  await page.mouse.click(centre.x, centre.y);
  const picked = await hooks(() => window.sphereset.selection());
  check(picked && picked.link === 'link1' && picked.index === 0, `link1's sphere selected (${JSON.stringify(picked)})`);
  let grip = null;
  for (let t = 8; t < 240 && !grip; t += 4) {
    await page.mouse.move(centre.x + t * d.x, centre.y + t * d.y);
    if (await hooks(() => window.sphereset.gizmoAxis()) === 'X') grip = { x: centre.x + t * d.x, y: centre.y + t * d.y };
  }
  check(grip !== null, 'the gizmo\'s x arrow lies along link1\'s own x on the screen');
  if (grip) {
    await page.mouse.down();
    for (let i = 1; i <= 5; i++) await page.mouse.move(grip.x + 8 * i * d.x, grip.y + 8 * i * d.y);
    await page.mouse.up();
    await page.waitForFunction((k, x) => window.sphereset.scene().solids[k].spheres[0][0] !== x,
      { timeout: 20000 }, k1, sphere[0]);
    const after = await hooks((k) => window.sphereset.scene().solids[k].spheres[0], k1);
    check(after[0] > sphere[0], `the drag moves x in link1's frame (${sphere[0]} -> ${after[0]})`);
    check(after[1] === sphere[1] && after[2] === sphere[2] && after[3] === sphere[3],
      `and leaves y, z and r bit for bit (${after.slice(1)} was ${sphere.slice(1)})`);
  }
  checkNoErrors(errors, 'with the robot tools');
});
