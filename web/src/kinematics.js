// Forward kinematics of a static page's robot, as the library's linkPoses (src/robot/
// kinematics.cpp) computes it, so that a page without a server can be posed: joint values
// clamped to their limits, mimic joints following their leaders (m * leader + offset, clamped),
// a revolute joint turning about its axis through its anchor by its value less its reference, a
// prismatic one sliding along its axis; a link's pose is its parent's times the joint's origin
// times that motion. The data is docs/view.md's "kinematics".
import { Matrix4, Vector3 } from 'three';

const clamp = (j, q) => (j.limits ? Math.min(j.limits[1], Math.max(j.limits[0], q)) : q);

// Every joint's value from the values given (name -> value) for joints that are not mimics.
export function jointValues(kinematics, given) {
  const values = {};
  for (const j of kinematics.joints) {
    if (j.mimic) continue;
    const v = Object.hasOwn(given, j.name) ? Number(given[j.name]) : j.reference;
    values[j.name] = clamp(j, Number.isFinite(v) ? v : j.reference);
  }
  // Mimics of mimics: as many passes as there are joints (a cycle stays at the reference).
  for (let pass = 0; pass < kinematics.joints.length; pass++) {
    let changed = false;
    for (const j of kinematics.joints) {
      if (!j.mimic || Object.hasOwn(values, j.name) || !Object.hasOwn(values, j.mimic.joint)) continue;
      values[j.name] = clamp(j, j.mimic.multiplier * values[j.mimic.joint] + j.mimic.offset);
      changed = true;
    }
    if (!changed) break;
  }
  for (const j of kinematics.joints) if (!Object.hasOwn(values, j.name)) values[j.name] = j.reference;
  return values;
}

// link name -> Matrix4 (link frame to root frame), for the links the root reaches.
export function linkPoses(kinematics, values) {
  const children = new Map();
  for (const j of kinematics.joints) {
    if (!children.has(j.parent)) children.set(j.parent, []);
    children.get(j.parent).push(j);
  }
  const poses = new Map();
  if (!kinematics.root) return poses;
  poses.set(kinematics.root, new Matrix4());
  const stack = [kinematics.root];
  while (stack.length) {
    const parent = stack.pop();
    for (const j of children.get(parent) || []) {
      if (poses.has(j.child)) continue;  // a loop: the first pose stays
      const q = values[j.name] - j.reference;
      const motion = new Matrix4();
      const axis = new Vector3(...j.axis);
      if (j.type === 'revolute' || j.type === 'continuous') {
        const anchor = new Vector3(...j.anchor);
        motion.makeRotationAxis(axis.normalize(), q);
        const turned = anchor.clone().applyMatrix4(motion);
        motion.setPosition(anchor.sub(turned));
      } else if (j.type === 'prismatic') {
        motion.makeTranslation(axis.multiplyScalar(q));
      }
      const origin = new Matrix4().set(...j.origin);
      poses.set(j.child, poses.get(parent).clone().multiply(origin).multiply(motion));
      stack.push(j.child);
    }
  }
  return poses;
}

// Per solid, 16 numbers row-major (the scene's "poses"): its link's pose, or the identity.
export function solidPoses(kinematics, solids, values) {
  const links = linkPoses(kinematics, values);
  return solids.map((s) => {
    const pose = links.get(s.link);
    return pose ? pose.clone().transpose().toArray() : new Matrix4().toArray();
  });
}
