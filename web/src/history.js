// Undo and redo on the page's side: each step is the list of edits (docs/view.md) that takes a
// solid's set back exactly, order included, sent to the server like any edit. Order matters: the
// steps before it address spheres by index. The API has no insert, so a deleted sphere comes
// back as an add at the end followed by sets that shift the spheres after it back into place.

// The edits that undo `edits` applied in order to `spheres`.
export function inverseEdits(spheres, edits) {
  const set = spheres.map((s) => s.slice());
  const inverse = [];
  for (const e of edits) {
    if (e.op === 'set') {
      inverse.unshift({ op: 'set', index: e.index, sphere: set[e.index] });
      set[e.index] = e.sphere.slice();
    } else if (e.op === 'add') {
      set.push(e.sphere.slice());
      inverse.unshift({ op: 'delete', index: set.length - 1 });
    } else if (e.op === 'delete') {
      const back = [{ op: 'add', sphere: set[set.length - 1] }];
      for (let j = e.index; j < set.length - 1; j++) back.push({ op: 'set', index: j, sphere: set[j] });
      set.splice(e.index, 1);
      inverse.unshift(...back);
    }
  }
  return inverse;
}

// The edits that turn the set `before` into `after` when only radii or centres changed (a
// bound), or null when the count changed.
export function differenceEdits(before, after) {
  if (before.length !== after.length) return null;
  const edits = [];
  after.forEach((s, i) => {
    if (s.some((v, j) => v !== before[i][j])) edits.push({ op: 'set', index: i, sphere: s.slice() });
  });
  return edits;
}

// The edits that turn the set `from` into `to` whatever their counts (a fit replaced it): sets
// of the common indices, then adds, or deletes from the end.
export function replaceEdits(from, to) {
  const edits = [];
  const common = Math.min(from.length, to.length);
  for (let i = 0; i < common; i++) {
    if (to[i].some((v, j) => v !== from[i][j])) edits.push({ op: 'set', index: i, sphere: to[i].slice() });
  }
  for (let i = common; i < to.length; i++) edits.push({ op: 'add', sphere: to[i].slice() });
  for (let i = from.length - 1; i >= to.length; i--) edits.push({ op: 'delete', index: i });
  return edits;
}

// A step is one change as the user made it: its parts ({ solid, edits }) are the edits that undo
// it on each solid it touched (a robot's fit touches every link; Ctrl+Z takes all of them back).
export class History {
  constructor() {
    this.undoSteps = [];  // { parts: [{ solid, edits }] }
    this.redoSteps = [];
  }

  record(solid, undoEdits) { this.recordParts([{ solid, edits: undoEdits }]); }

  // One step over several solids; parts without edits are left out.
  recordParts(parts) {
    const kept = parts.filter((p) => p.edits && p.edits.length);
    if (!kept.length) return;
    this.undoSteps.push({ parts: kept });
    this.redoSteps.length = 0;
  }

  // A solid's set was replaced (another tree level): its parts no longer apply.
  forget(solid) {
    // In place: the stacks stay the same arrays.
    const without = (steps) => {
      const kept = steps
        .map((s) => ({ parts: s.parts.filter((p) => p.solid !== solid) }))
        .filter((s) => s.parts.length);
      steps.splice(0, steps.length, ...kept);
    };
    without(this.undoSteps);
    without(this.redoSteps);
  }

  get canUndo() { return this.undoSteps.length > 0; }
  get canRedo() { return this.redoSteps.length > 0; }
}
