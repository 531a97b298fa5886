// One solid's displayed mesh: grey, with the triangles the certificate finds uncovered drawn
// red. The triangles are reordered into two index groups (covered, then uncovered) so each
// group has one material and a shared vertex cannot smear red onto its covered neighbours.
import { BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshStandardMaterial } from 'three';

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
    const uncovered = new MeshStandardMaterial({
      color: 0xe01010, emissive: 0x500000, roughness: 0.8, side: DoubleSide, flatShading: true,
    });
    this.mesh = new Mesh(this.geometry, [covered, uncovered]);
    this.redCount = 0;
    this.setUncovered([]);
  }

  // Returns how many distinct triangles are drawn red.
  setUncovered(triangleList) {
    const red = new Uint8Array(this.triangles);
    let redCount = 0;
    for (const t of triangleList || []) {
      if (Number.isInteger(t) && t >= 0 && t < this.triangles && !red[t]) {
        red[t] = 1;
        redCount++;
      }
    }
    const ordered = new Uint32Array(this.indices.length);
    let coveredAt = 0;
    let redAt = 3 * (this.triangles - redCount);
    for (let t = 0; t < this.triangles; t++) {
      const at = red[t] ? redAt : coveredAt;
      ordered[at] = this.indices[3 * t];
      ordered[at + 1] = this.indices[3 * t + 1];
      ordered[at + 2] = this.indices[3 * t + 2];
      if (red[t]) redAt += 3;
      else coveredAt += 3;
    }
    this.geometry.setIndex(new BufferAttribute(ordered, 1));
    this.geometry.clearGroups();
    this.geometry.addGroup(0, 3 * (this.triangles - redCount), 0);
    this.geometry.addGroup(3 * (this.triangles - redCount), 3 * redCount, 1);
    this.redCount = redCount;
    return redCount;
  }
}
