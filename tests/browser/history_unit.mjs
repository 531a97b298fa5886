// The page's undo and redo (web/src/history.js) without a browser: random edits applied to a set
// as the server applies them; undoing step by step gives back each earlier set exactly, in its
// order, and redoing each later one.
import assert from 'node:assert/strict';
import { History, differenceEdits, inverseEdits } from '../../web/src/history.js';

// The server's rule (docs/view.md): edits in order, indices into the set as each edit finds it,
// an added sphere at the end.
function apply(spheres, edits) {
  const set = spheres.map((s) => s.slice());
  for (const e of edits) {
    if (e.op === 'set') set[e.index] = e.sphere.slice();
    else if (e.op === 'add') set.push(e.sphere.slice());
    else set.splice(e.index, 1);
  }
  return set;
}

let seed = 7;
const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
const sphere = () => [random(), random(), random(), 0.1 + random()];

function randomEdits(set) {
  const edits = [];
  let n = set.length;
  for (let k = 1 + Math.floor(random() * 3); k > 0; k--) {
    const choice = n === 0 ? 1 : Math.floor(random() * 3);
    if (choice === 0) edits.push({ op: 'set', index: Math.floor(random() * n), sphere: sphere() });
    else if (choice === 1) { edits.push({ op: 'add', sphere: sphere() }); n++; }
    else { edits.push({ op: 'delete', index: Math.floor(random() * n) }); n--; }
  }
  return edits;
}

for (let trial = 0; trial < 200; trial++) {
  let set = [sphere(), sphere(), sphere()];
  const history = [set];
  const undo = [];
  for (let step = 0; step < 6; step++) {
    const edits = randomEdits(set);
    undo.push(inverseEdits(set, edits));
    set = apply(set, edits);
    history.push(set);
  }
  const redo = [];
  for (let step = undo.length - 1; step >= 0; step--) {
    const edits = undo.pop();
    redo.push(inverseEdits(set, edits));
    set = apply(set, edits);
    assert.deepEqual(set, history[step], `trial ${trial}: undo to step ${step}`);
  }
  for (let step = 1; redo.length; step++) {
    const edits = redo.pop();
    set = apply(set, edits);
    assert.deepEqual(set, history[step], `trial ${trial}: redo to step ${step}`);
  }
}

const before = [[0, 0, 0, 1], [1, 0, 0, 1]];
const after = [[0, 0, 0, 1.5], [1, 0, 0, 1]];
assert.deepEqual(apply(after, differenceEdits(after, before)), before, 'a bound is undone by sets');
assert.equal(differenceEdits(after, [[0, 0, 0, 1]]), null, 'no set edits between sets of other sizes');
// A change of several solids (a robot's fit) is one step of several parts; parts without edits are
// left out, and forgetting a solid (another tree level) drops its parts only.
const history = new History();
history.recordParts([{ solid: 0, edits: [{ op: 'delete', index: 0 }] }, { solid: 1, edits: [] },
  { solid: 2, edits: [{ op: 'add', sphere: [0, 0, 0, 1] }] }]);
assert.equal(history.undoSteps.length, 1, 'one step for the whole change');
assert.deepEqual(history.undoSteps[0].parts.map((p) => p.solid), [0, 2], 'its parts with edits');
history.record(1, [{ op: 'set', index: 0, sphere: [1, 1, 1, 1] }]);
history.forget(0);
assert.deepEqual(history.undoSteps.map((s) => s.parts.map((p) => p.solid)), [[2], [1]],
  "forgetting solid 0 keeps the other solids' parts");
history.forget(2);
assert.deepEqual(history.undoSteps.map((s) => s.parts.map((p) => p.solid)), [[1]],
  'a step left without parts is dropped');
assert.ok(history.canUndo && !history.canRedo);
console.log('PASS');
