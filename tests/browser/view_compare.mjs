// Two sets of the box compared (`sphereset view MESH A B`), by mouse and keyboard: the compare
// table gives both certificates (A covers, B does not), the status is A's; the layout list puts
// B over A (wireframe), beside it, or either alone; B's sphere can be selected, named with its
// file, but not edited.
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { readFileSync } from 'node:fs';
import { writeBox, writeBoxSpheres, writeRobot } from './fixtures.mjs';
import { check, checkNoErrors, openPage, pageStatus, runTest, startView } from './harness.mjs';

await runTest(async (args, browser) => {
  const mesh = writeBox(args.work);
  const a = writeBoxSpheres(args.work);
  const b = join(args.work, 'small.txt');
  writeFileSync(b, '0 0 0 0.25\n');
  const { page, errors } = await openPage(browser, (await startView(args, [mesh.path, a.path, b])).url);
  const hooks = (fn, ...rest) => page.evaluate(fn, ...rest);

  check(await page.$eval('#compare-box', (e) => !e.classList.contains('hidden')), 'the compare box is shown');
  const table = await page.$$eval('#compare-table tr', (rows) => rows.map((r) => [...r.children].map((td) => td.textContent)));
  const row = (name) => table.find((r) => r[0] === name) || [];
  check(row('set')[1] === 'box_spheres.txt' && row('set')[2] === 'small.txt', `both files named (${row('set')})`);
  check(row('covered')[1] === '1 of 1' && row('covered')[2] === '0 of 1', `A covers, B does not (${row('covered')})`);
  const er = await hooks(() => [window.sphereset.certificate(0).er_sum, window.sphereset.certificate(1).er_sum]);
  check(Number(row('E_r summed')[1]) === Number(er[0].toPrecision(6)) && Number(row('E_r summed')[2]) === Number(er[1].toPrecision(6)),
    `each set's E_r is its certificate's (${row('E_r summed')})`);
  check(await pageStatus(page) === 'covered', 'the status is the first set\'s: covered');

  // Layouts, chosen by keys.
  await page.$eval('#compare-layout', (e) => e.scrollIntoView());
  await page.focus('#compare-layout');
  await page.keyboard.press('ArrowDown');  // side by side
  const side = await hooks(() => window.sphereset.linkWorldPosition(1));
  check(side[0] > 1, `side by side: B stands beside A (x ${side[0].toFixed(3)})`);
  await page.keyboard.press('ArrowDown');  // A alone
  let v = await hooks(() => window.sphereset.visibility());
  check(v.solids[0].drawn && !v.solids[1].drawn, 'A alone');
  await page.keyboard.press('ArrowDown');  // B alone
  v = await hooks(() => window.sphereset.visibility());
  check(!v.solids[0].drawn && v.solids[1].drawn, 'B alone');

  // B's sphere, clicked: selected and named with its file, its fields locked.
  const at = await hooks(() => window.sphereset.screenOf(1, [0, 0, 0]));
  await page.mouse.click(at.x, at.y);
  const selected = await hooks(() => window.sphereset.selection());
  check(selected && selected.solid === 1 && selected.link.includes('small.txt'), `B's sphere selected (${JSON.stringify(selected)})`);
  check(await page.$eval('#sel-r', (e) => e.disabled), 'its fields cannot be typed in');
  check(await hooks(() => window.sphereset.gizmoAxis()) === null, 'and it has no gizmo handle lit');
  const refused = await hooks(() => window.sphereset.setSphere(1, 0, [0, 0, 0, 1]).then(() => null, (e) => e.message));
  check(refused && refused.includes('compared set'), `an edit of B is refused (${refused})`);
  checkNoErrors(errors.filter((e) => !e.includes('400')), 'while comparing');

  const robot = writeRobot(args.work);
  const other = join(args.work, 'two_link_b.yml');
  writeFileSync(other, 'collision_spheres:\n  link1:\n    - "center": [0, 0, 0.2]\n      "radius": 0.3\n');
  const before = readFileSync(other, 'utf8');
  const live = await openPage(browser, (await startView(args, [robot.urdf, robot.spheres, other])).url);
  const rows = await live.page.$$eval('#link-list .link .name', (n) => n.map((x) => x.textContent));
  check(rows.includes('link1 [two_link_b.yml]') && rows.includes('link1'), `B's link listed with its file (${rows.join(', ')})`);
  const scene = await live.page.evaluate(() => window.sphereset.scene());
  const a1 = scene.solids.findIndex((s) => s.link === 'link1' && s.set === 0);
  const b1 = scene.solids.findIndex((s) => s.link === 'link1' && s.set === 1);
  await live.page.$eval('input[data-joint="joint1"]', (e) => e.scrollIntoView());
  const slider = await (await live.page.$('input[data-joint="joint1"]')).boundingBox();
  await live.page.mouse.click(slider.x + slider.width * 0.8, slider.y + slider.height / 2);
  await live.page.waitForFunction(() => window.sphereset.scene().joints[0].value !== 0, { timeout: 20000 });
  // A point of link1's frame away from its joint lands on the same pixel in both sets.
  const [pa, pb, rest] = await live.page.evaluate((i, j) => [window.sphereset.screenOf(i, [0, 0, 0.4]),
    window.sphereset.screenOf(j, [0, 0, 0.4]), window.sphereset.scene().joints[0].value], a1, b1);
  check(rest > 0.5 && Math.abs(pa.x - pb.x) < 1e-6 && Math.abs(pa.y - pb.y) < 1e-6,
    `a joint (${rest.toFixed(3)}) moves both sets' link1 alike (${pa.x.toFixed(1)},${pa.y.toFixed(1)})`);
  await live.page.click('#save');
  await live.page.waitForFunction(() => document.getElementById('message').textContent.startsWith('saved'), { timeout: 20000 });
  check(readFileSync(other, 'utf8') === before, 'Save leaves the compared file as it was');
  check((await live.page.$eval('#message', (e) => e.textContent)).includes('two_link_spheres.yml'), 'and writes the first');
  checkNoErrors(live.errors, 'while comparing robots');
});
