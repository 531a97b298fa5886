// One solid's displayed mesh: grey, with the triangles the certificate finds uncovered (the
// gaps) drawn in the gap colour (colors.js, on no sphere ramp) on top: after the translucent
// spheres, so that a sphere in front does not wash them out. The gap triangles are a mesh of their own (a child of the grey one) that shares
// the grey mesh's vertex buffers and has only their indices: an edit replaces that small index,
// never the whole mesh's, which on a mesh of a million triangles took seconds to upload and
// redraw. A vertex shared with a covered neighbour cannot smear red onto it.
import {
  Box3, BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshBasicMaterial, MeshStandardMaterial, Triangle, Vector3,
} from 'three';
import { gapColor } from './colors.js';

export class SolidMesh {
  constructor({ positions, indices }) {
    this.triangles = indices.length / 3;
    this.indices = indices;
    this.geometry = new BufferGeometry();
    this.geometry.setAttribute('position', new BufferAttribute(positions, 3));
    this.geometry.setIndex(new BufferAttribute(indices, 1));
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingBox();
    this.geometry.computeBoundingSphere();
    const covered = new MeshStandardMaterial({
      color: 0xb8b8b0, roughness: 0.8, metalness: 0.0, side: DoubleSide, flatShading: true,
    });
    this.mesh = new Mesh(this.geometry, covered);
    // Drawn over the grey triangles they coincide with (pulled towards the camera in depth),
    // unlit so that no shading darkens them, and after the spheres (which write no depth), so
    // that they show through every sphere in front of them.
    const uncovered = new MeshBasicMaterial({
      color: gapColor, side: DoubleSide,
      polygonOffset: true, polygonOffsetFactor: -1, polygonOffsetUnits: -1,
    });
    this.redGeometry = new BufferGeometry();
    this.redGeometry.setAttribute('position', this.geometry.getAttribute('position'));
    this.redGeometry.setAttribute('normal', this.geometry.getAttribute('normal'));
    this.redGeometry.boundingBox = this.geometry.boundingBox;
    this.redGeometry.boundingSphere = this.geometry.boundingSphere;
    this.red = new Mesh(this.redGeometry, uncovered);
    this.red.raycast = () => {};  // picking goes to the solid itself
    this.red.renderOrder = 2;     // after the spheres (renderOrder 1)
    this.mesh.add(this.red);
    this.redCount = 0;
    this.setUncovered([]);
  }

  setWireframe(on) {
    this.mesh.material.wireframe = on;
  }

  // The largest connected patch (triangles sharing a vertex) of the gap triangles by area:
  // { area, box (solid frame), triangles }, or null when there are no gaps.
  largestGap() {
    if (!this.gaps || !this.gaps.length) return null;
    const parent = new Map();
    const find = (v) => {
      while (parent.get(v) !== v) {
        parent.set(v, parent.get(parent.get(v)));
        v = parent.get(v);
      }
      return v;
    };
    const join = (a, b) => { parent.set(find(a), find(b)); };
    for (const t of this.gaps) {
      for (let j = 0; j < 3; j++) {
        const v = this.indices[3 * t + j];
        if (!parent.has(v)) parent.set(v, v);
      }
      join(this.indices[3 * t], this.indices[3 * t + 1]);
      join(this.indices[3 * t], this.indices[3 * t + 2]);
    }
    const position = this.geometry.getAttribute('position');
    const patches = new Map();
    const [a, b, c] = [new Vector3(), new Vector3(), new Vector3()];
    for (const t of this.gaps) {
      const root = find(this.indices[3 * t]);
      if (!patches.has(root)) patches.set(root, { area: 0, box: new Box3(), triangles: 0 });
      const patch = patches.get(root);
      a.fromBufferAttribute(position, this.indices[3 * t]);
      b.fromBufferAttribute(position, this.indices[3 * t + 1]);
      c.fromBufferAttribute(position, this.indices[3 * t + 2]);
      patch.area += new Triangle(a, b, c).getArea();
      patch.box.expandByPoint(a).expandByPoint(b).expandByPoint(c);
      patch.triangles++;
    }
    let best = null;
    for (const patch of patches.values()) if (!best || patch.area > best.area) best = patch;
    return best;
  }

  // Returns how many distinct triangles are drawn as gaps.
  setUncovered(triangleList) {
    const seen = new Set();
    for (const t of triangleList || []) {
      if (Number.isInteger(t) && t >= 0 && t < this.triangles) seen.add(t);
    }
    // The gap index grows by doubling (a replaced index keeps its GL buffer until the page
    // closes: a few times over a session, not once per edit); an edit rewrites the part in use.
    const needed = 3 * seen.size;
    let index = this.redGeometry.getIndex();
    if (!index || index.array.length < needed) {
      const capacity = Math.max(needed, 2 * (index ? index.array.length : 3 * 1024));
      index = new BufferAttribute(new Uint32Array(capacity), 1);
      this.redGeometry.setIndex(index);
    }
    let at = 0;
    for (const t of seen) {
      index.array[at++] = this.indices[3 * t];
      index.array[at++] = this.indices[3 * t + 1];
      index.array[at++] = this.indices[3 * t + 2];
    }
    index.clearUpdateRanges();
    if (needed > 0) index.addUpdateRange(0, needed);
    index.needsUpdate = true;
    this.redGeometry.setDrawRange(0, needed);
    this.red.visible = seen.size > 0;
    this.redCount = seen.size;
    this.gaps = [...seen];
    return this.redCount;
  }
}
