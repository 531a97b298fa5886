// A robot's self-collision on the page: the pairs in contact at the current pose (the server's
// answer, docs/view.md "collisions"), listed and drawn as a red segment between the two most
// overlapping spheres of each pair, and the allowed pairs (an SRDF's, or the adjacent links).
// Which pairs are in contact is the library's rule; which spheres the segment joins is only a
// drawing choice.
import { Vector3 } from 'three';

const $ = (id) => document.getElementById(id);

// collisions: the scene's, or null (a mesh). stale: the robot was posed on a static page after
// the pairs were written.
export function showCollisions(collisions, stale) {
  $('collision-box').classList.toggle('hidden', !collisions);
  if (!collisions) return;
  const contact = collisions.contact || [];
  $('contact-summary').textContent = stale
    ? 'at the pose the page was written (posed since: not checked here)'
    : contact.length ? `${contact.length} pair${contact.length > 1 ? 's' : ''} in contact at this pose`
      : 'no pair in contact at this pose';
  $('contact-list').replaceChildren(...(stale ? [] : contact).map(([a, b]) => {
    const row = document.createElement('div');
    row.className = 'pair';
    row.textContent = `${a} – ${b}`;
    return row;
  }));
  const allowed = collisions.allowed || [];
  const from = collisions.allowed_source === 'srdf' ? 'from the SRDF' : 'adjacent links';
  $('allowed-summary').textContent = `${allowed.length} allowed pairs (${from})`;
  $('allowed-list').replaceChildren(...allowed.map(([a, b]) => {
    const row = document.createElement('div');
    row.textContent = `${a} – ${b}`;
    return row;
  }));
}

// Per pair in contact: [from, to] in world coordinates, the centres of its two spheres that
// overlap most.
export function contactSegments(scene, viewer) {
  const contact = (scene.collisions && scene.collisions.contact) || [];
  // The edited set's links (a compared set has no contacts of its own).
  const byLink = new Map(scene.solids.map((s, k) => [s, k]).filter(([s]) => s.set !== 1).map(([s, k]) => [s.link, k]));
  const placed = (k) => {
    const group = viewer.solids[k].group;
    group.updateMatrixWorld(true);
    return scene.solids[k].spheres.map(([x, y, z, r]) => ({ c: new Vector3(x, y, z).applyMatrix4(group.matrixWorld), r }));
  };
  const segments = [];
  for (const [a, b] of contact) {
    if (!byLink.has(a) || !byLink.has(b)) continue;
    const sa = placed(byLink.get(a));
    const sb = placed(byLink.get(b));
    let best = null;
    for (const p of sa) {
      for (const q of sb) {
        const depth = p.r + q.r - p.c.distanceTo(q.c);
        if (!best || depth > best.depth) best = { depth, from: p.c, to: q.c };
      }
    }
    if (best) segments.push([best.from.toArray(), best.to.toArray()]);
  }
  return segments;
}
