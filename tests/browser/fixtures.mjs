// The tests' inputs, written by the tests themselves: a box mesh, a sphere set around it, and a
// small robot (three box links on a revolute and a fixed joint) with a cuRobo-style sphere file.
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';

// A box of half sizes (0.5, 0.3, 0.2), each face cut into a 4x4 grid, so that moving a sphere
// leaves some triangles covered and turns others red. Outward triangles, vertices from 0.
export function boxMesh() {
  const half = [0.5, 0.3, 0.2];
  const n = 4;
  const vertices = [];
  const ids = new Map();
  const vertex = (p) => {
    const key = p.map((v) => v.toFixed(6)).join(' ');
    if (!ids.has(key)) {
      ids.set(key, vertices.length);
      vertices.push(p);
    }
    return ids.get(key);
  };
  const triangles = [];
  for (const axis of [0, 1, 2]) {
    const u = (axis + 1) % 3;
    const v = (axis + 2) % 3;
    for (const side of [-1, 1]) {
      for (let i = 0; i < n; i++) {
        for (let j = 0; j < n; j++) {
          const at = (a, b) => {
            const p = [0, 0, 0];
            p[u] = (-1 + (2 * a) / n) * half[u];
            p[v] = (-1 + (2 * b) / n) * half[v];
            p[axis] = side * half[axis];
            return vertex(p);
          };
          const [p00, p10, p11, p01] = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
          if (side > 0) triangles.push([p00, p10, p11], [p00, p11, p01]);
          else triangles.push([p00, p11, p10], [p00, p01, p11]);
        }
      }
    }
  }
  return { vertices, triangles, half, diagonal: 2 * Math.hypot(...half) };
}

export function writeBox(dir) {
  const { vertices, triangles, diagonal } = boxMesh();
  const path = join(dir, 'box.obj');
  writeFileSync(path, `${vertices.map((p) => `v ${p.join(' ')}`).join('\n')}\n` +
    `${triangles.map((t) => `f ${t.map((i) => i + 1).join(' ')}`).join('\n')}\n`);
  return { path, triangles: triangles.length, diagonal };
}

// One sphere around the whole box (it covers) and two small ones inside it.
export function writeBoxSpheres(dir) {
  const path = join(dir, 'box_spheres.txt');
  writeFileSync(path, '# x y z r\n0 0 0 0.65\n0.3 0 0 0.2\n-0.3 0 0 0.2\n');
  return { path, count: 3 };
}

export function writeRobot(dir) {
  const urdf = join(dir, 'two_link.urdf');
  writeFileSync(urdf, `<?xml version="1.0"?>
<robot name="two_link">
  <link name="base_link">
    <collision><origin xyz="0 0 0.05"/><geometry><box size="0.3 0.3 0.1"/></geometry></collision>
  </link>
  <link name="link1">
    <collision><origin xyz="0 0 0.2"/><geometry><box size="0.1 0.1 0.4"/></geometry></collision>
  </link>
  <link name="link2">
    <collision><origin xyz="0.1 0 0"/><geometry><box size="0.2 0.08 0.08"/></geometry></collision>
  </link>
  <joint name="joint1" type="revolute">
    <parent link="base_link"/><child link="link1"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 1 0"/>
    <limit lower="-1.5" upper="1.5" effort="10" velocity="1"/>
  </joint>
  <joint name="joint2" type="fixed">
    <parent link="link1"/><child link="link2"/>
    <origin xyz="0 0 0.4"/>
  </joint>
</robot>
`);
  const spheres = join(dir, 'two_link_spheres.yml');
  const sphere = (c, r) => `    - "center": [${c.join(', ')}]\n      "radius": ${r}\n`;
  writeFileSync(spheres, 'collision_spheres:\n' +
    `  base_link:\n${sphere([0, 0, 0.05], 0.25)}` +
    `  link1:\n${sphere([0, 0, 0.1], 0.13)}${sphere([0, 0, 0.3], 0.13)}` +
    `  link2:\n${sphere([0.1, 0, 0], 0.13)}`);
  // link2's frame sits 0.4 above joint1 (at z 0.1), on link1, which turns about y.
  const link2Origin = (q) => [0.4 * Math.sin(q), 0, 0.1 + 0.4 * Math.cos(q)];
  return { urdf, spheres, counts: { base_link: 1, link1: 2, link2: 1 }, link2Origin };
}
