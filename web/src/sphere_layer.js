// One solid's spheres as one instanced, translucent mesh; each sphere coloured by its place on
// the ramp (colors.js). The instance buffers grow by doubling, so adding a sphere rarely rebuilds.
import {
  Color, InstancedMesh, Matrix4, MeshStandardMaterial, Quaternion, SphereGeometry, Vector3,
} from 'three';
import { rampColor } from './colors.js';

// Fewer triangles per sphere when there are many: a few thousand spheres stay interactive even
// with software rendering.
const detailedSphere = new SphereGeometry(1, 32, 16);
const coarseSphere = new SphereGeometry(1, 16, 10);
const manySpheres = 1024;

export class SphereLayer {
  constructor(parent, solidIndex) {
    this.parent = parent;
    this.solidIndex = solidIndex;
    this.material = new MeshStandardMaterial({
      color: 0xffffff, transparent: true, opacity: 0.35, depthWrite: false, roughness: 0.5,
    });
    this.mesh = null;
    this.spheres = [];
  }

  get count() { return this.mesh ? this.mesh.count : 0; }

  // spheres: [[x,y,z,r], ...]; shades: per sphere, its place on the ramp (0 to 1).
  update(spheres, shades) {
    this.spheres = spheres.map((s) => s.slice());
    this.ensureCapacity(spheres.length);
    const m = new Matrix4();
    const color = new Color();
    const identity = new Quaternion();
    for (let i = 0; i < spheres.length; i++) {
      const [x, y, z, r] = spheres[i];
      m.compose(new Vector3(x, y, z), identity, new Vector3(r, r, r));
      this.mesh.setMatrixAt(i, m);
      this.mesh.setColorAt(i, rampColor(shades[i], color));
    }
    this.mesh.count = spheres.length;
    this.mesh.instanceMatrix.needsUpdate = true;
    this.mesh.instanceColor.needsUpdate = true;
    this.mesh.computeBoundingSphere();
    this.mesh.computeBoundingBox();
  }

  setOpacity(opacity) {
    this.material.opacity = Math.min(1, Math.max(0.05, opacity));
    this.material.needsUpdate = true;
  }

  // Sphere i's colour as [r, g, b], 0 to 1.
  colorOf(index) {
    if (!this.mesh || index >= this.mesh.count) return null;
    const c = new Color();
    this.mesh.getColorAt(index, c);
    return [c.r, c.g, c.b];
  }

  // Moves one sphere while it is dragged, before the server has answered.
  preview(index, sphere) {
    if (!this.mesh || index >= this.mesh.count) return;
    const [x, y, z, r] = sphere;
    const m = new Matrix4().compose(new Vector3(x, y, z), new Quaternion(), new Vector3(r, r, r));
    this.mesh.setMatrixAt(index, m);
    this.mesh.instanceMatrix.needsUpdate = true;
    this.mesh.computeBoundingSphere();
  }

  ensureCapacity(n) {
    if (this.mesh && this.mesh.instanceMatrix.count >= n) return;
    const capacity = Math.max(16, 2 ** Math.ceil(Math.log2(Math.max(1, n))));
    if (this.mesh) {
      this.parent.remove(this.mesh);
      this.mesh.dispose();
    }
    const geometry = capacity > manySpheres ? coarseSphere : detailedSphere;
    this.mesh = new InstancedMesh(geometry, this.material, capacity);
    this.mesh.userData.solid = this.solidIndex;
    this.mesh.renderOrder = 1;  // after the opaque solid, so the solid shows through
    // The colour buffer must exist before the first draw for the shader to use it.
    this.mesh.setColorAt(0, new Color(1, 1, 1));
    this.parent.add(this.mesh);
  }
}
