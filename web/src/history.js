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

export class History {
  constructor() {
    this.undoSteps = [];  // { solid, edits }: the edits that undo a change
    this.redoSteps = [];
  }

  record(solid, undoEdits) {
    if (!undoEdits || !undoEdits.length) return;
    this.undoSteps.push({ solid, edits: undoEdits });
    this.redoSteps = [];
  }

  // A solid's set was replaced (another tree level): its steps no longer apply.
  forget(solid) {
    this.undoSteps = this.undoSteps.filter((s) => s.solid !== solid);
    this.redoSteps = this.redoSteps.filter((s) => s.solid !== solid);
  }

  get canUndo() { return this.undoSteps.length > 0; }
  get canRedo() { return this.redoSteps.length > 0; }
}
