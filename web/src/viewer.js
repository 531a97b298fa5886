// The three.js view: camera, lights, orbit controls, one group per solid placed by its pose,
// the solid's mesh and spheres inside it, picking and the gizmo that drags a sphere's centre.
import {
  Box3, BufferGeometry, Color, DirectionalLight, Float32BufferAttribute, Frustum, LineBasicMaterial, LineSegments, Group, HemisphereLight, Matrix4, Mesh, MeshBasicMaterial,
  Object3D, PerspectiveCamera, Raycaster, Scene, SphereGeometry, Vector2, Vector3, WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';
import { SolidMesh } from './solid_mesh.js';
import { SphereLayer } from './sphere_layer.js';

export class Viewer {
  constructor(container, { zUp }) {
    this.container = container;
    // preserveDrawingBuffer: the canvas can be read (PNG button, screenshots) at any time.
    this.renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    container.appendChild(this.renderer.domElement);
    this.scene = new Scene();
    this.scene.background = new Color(0xf4f4f2);
    this.camera = new PerspectiveCamera(45, 1, 0.01, 1000);
    if (zUp) this.camera.up.set(0, 0, 1);
    this.scene.add(new HemisphereLight(0xffffff, 0x888877, 1.6));
    const key = new DirectionalLight(0xffffff, 1.4);
    key.position.set(1, 2, 3);
    this.camera.add(key);  // the key light follows the camera: the side in view is lit
    this.scene.add(this.camera);

    this.orbit = new OrbitControls(this.camera, this.renderer.domElement);
    this.orbit.addEventListener('change', () => this.requestRender());

    this.gizmo = new TransformControls(this.camera, this.renderer.domElement);
    // The arrows along the solid's own axes (a link's frame): a drag along one changes that
    // coordinate of the centre alone.
    this.gizmo.space = 'local';
    this.gizmo.addEventListener('change', () => this.requestRender());
    this.gizmo.addEventListener('dragging-changed', (e) => { this.orbit.enabled = !e.value; });
    this.scene.add(this.gizmo.getHelper());
    dropFreeMoveHandle(this.gizmo);
    this.handle = new Object3D();  // what the gizmo moves: the selected sphere's centre
    this.outline = new Mesh(new SphereGeometry(1, 24, 12),
      new MeshBasicMaterial({ color: 0x111111, wireframe: true, transparent: true, opacity: 0.35 }));
    this.handle.add(this.outline);

    // Self-collision contacts: red segments drawn over everything.
    this.contacts = new LineSegments(new BufferGeometry(),
      new LineBasicMaterial({ color: 0xd00000, depthTest: false, transparent: true }));
    this.contacts.renderOrder = 3;
    this.scene.add(this.contacts);
    this.solids = [];  // { group, mesh: SolidMesh, spheres: SphereLayer, repaired: SolidMesh|null }
    this.display = { mesh: true, spheres: true, wireframe: false, opacity: 0.35, surface: 'displayed' };
    this.raycaster = new Raycaster();
    this.renderPending = false;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  // sets: per solid, 0 (the set edited) or 1 (the set compared with it).
  build(geometries, poses, sets = []) {
    this.sets = sets;
    geometries.forEach((geometry, k) => {
      const group = new Group();
      group.matrixAutoUpdate = false;
      const mesh = new SolidMesh(geometry);
      mesh.mesh.userData.solid = k;
      group.add(mesh.mesh);
      const spheres = new SphereLayer(group, k);
      if (sets[k] === 1) spheres.material.wireframe = true;  // told apart when overlaid
      this.scene.add(group);
      this.solids.push({ group, mesh, spheres, repaired: null, shown: true });
    });
    this.setPoses(poses);
  }

  // poses: per solid, 16 numbers, row-major 4x4, solid frame to world. Side by side, the
  // compared set stands beside the first, shifted along x by its width and a margin.
  setPoses(poses) {
    this.poses = poses;
    this.solids.forEach(({ group }, k) => {
      const p = poses && poses[k];
      if (p && p.length === 16) group.matrix.set(...p);
      else group.matrix.identity();
      group.matrixWorldNeedsUpdate = true;
    });
    this.scene.updateMatrixWorld(true);
    if (this.compareLayout === 'side') {
      const first = this.sceneBox(this.solids.filter((_, k) => this.sets[k] !== 1));
      const shift = new Matrix4().makeTranslation(1.15 * (first.max.x - first.min.x) + 1e-6, 0, 0);
      this.solids.forEach(({ group }, k) => {
        if (this.sets[k] === 1) group.matrix.premultiply(shift);
      });
      this.scene.updateMatrixWorld(true);
    }
    this.requestRender();
  }

  // 'overlaid' (the compared set in wireframe over the first), 'side', 'a' or 'b' alone.
  setCompareLayout(layout) {
    this.compareLayout = layout;
    this.solids.forEach((solid, k) => {
      const set = this.sets[k] || 0;
      solid.compareHidden = (layout === 'a' && set === 1) || (layout === 'b' && set === 0);
    });
    this.setPoses(this.poses);
    this.applyDisplay();
  }

  // --- what is drawn -----------------------------------------------------------------------

  // A solid (link) with its spheres, shown or hidden.
  setSolidShown(k, shown) {
    this.solids[k].shown = shown;
    this.applyDisplay();
  }

  // display: { mesh, spheres, wireframe, opacity (0 to 1), surface: 'displayed' | 'repaired' }.
  setDisplay(changes) {
    Object.assign(this.display, changes);
    this.applyDisplay();
  }

  // A repaired solid's own surface, drawn instead of its original triangles when the surface
  // chosen is 'repaired' (the gaps are listed against the original triangles: they stay drawn
  // there).
  setRepairedGeometry(k, geometry) {
    const solid = this.solids[k];
    if (solid.repaired) solid.group.remove(solid.repaired.mesh);
    solid.repaired = new SolidMesh(geometry);
    solid.repaired.mesh.userData.solid = k;
    solid.group.add(solid.repaired.mesh);
    this.applyDisplay();
  }

  applyDisplay() {
    const d = this.display;
    for (const solid of this.solids) {
      solid.group.visible = solid.shown && !solid.compareHidden;
      const repaired = d.surface === 'repaired' && solid.repaired !== null;
      // The grey surface's material is hidden, not the mesh: its gap triangles (a child) stay.
      solid.mesh.mesh.material.visible = d.mesh && !repaired;
      if (solid.repaired) solid.repaired.mesh.material.visible = d.mesh && repaired;
      for (const m of [solid.mesh, solid.repaired]) if (m) m.setWireframe(d.wireframe);
      if (solid.spheres.mesh) solid.spheres.mesh.visible = d.spheres;
      solid.spheres.setOpacity(d.opacity);
    }
    this.requestRender();
  }

  // segments: [[from, to], ...] in world coordinates.
  setContactSegments(segments) {
    const points = segments.flatMap(([a, b]) => [...a, ...b]);
    this.contacts.geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
    this.contacts.geometry.computeBoundingSphere();
    this.contacts.visible = segments.length > 0;
    this.contactCount = segments.length;
    this.requestRender();
  }

  // What is drawn, for the hooks.
  visibility() {
    return {
      display: { ...this.display },
      solids: this.solids.map((s) => ({
        shown: s.shown,
        drawn: s.group.visible,
        mesh: s.mesh.mesh.material.visible,
        repaired: s.repaired ? s.repaired.mesh.material.visible : null,
        wireframe: s.mesh.mesh.material.wireframe,
        spheres: Boolean(s.spheres.mesh && s.spheres.mesh.visible),
        opacity: s.spheres.material.opacity,
      })),
      contactSegments: this.contactCount || 0,
    };
  }

  // The meshes a ray can hit: those drawn.
  drawnMeshes() {
    const meshes = [];
    for (const s of this.solids) {
      if (!s.group.visible) continue;
      for (const m of [s.mesh, s.repaired]) if (m && m.mesh.material.visible) meshes.push(m.mesh);
    }
    return meshes;
  }

  worldOrigin(k) {
    const group = this.solids[k].group;
    group.updateMatrixWorld(true);
    return new Vector3().setFromMatrixPosition(group.matrixWorld).toArray();
  }

  // Fits the camera to every mesh and sphere, looking from the default direction.
  frame() {
    const direction = this.camera.up.z === 1 ? new Vector3(1.2, -1.6, 0.9) : new Vector3(1.2, 0.9, 1.6);
    this.frameBox(this.sceneBox(), direction);
  }

  // Reframes, looking from where the camera looks now, when part of the scene has left the view
  // (a joint moved the robot); otherwise leaves the camera alone.
  keepInView() {
    const box = this.sceneBox();
    if (this.boxInView(box)) return;
    this.frameBox(box, this.camera.position.clone().sub(this.orbit.target));
  }

  // Whether the box (world frame) lies inside the camera's view.
  boxInView(box) {
    this.camera.updateMatrixWorld(true);
    const frustum = new Frustum().setFromProjectionMatrix(
      new Matrix4().multiplyMatrices(this.camera.projectionMatrix, this.camera.matrixWorldInverse));
    const corner = new Vector3();
    for (let i = 0; i < 8; i++) {
      corner.set(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z);
      if (!frustum.containsPoint(corner)) return false;
    }
    return true;
  }

  // Where point [x,y,z] of solid k's frame is on the page, in client pixels.
  screenOf(k, point) {
    const group = this.solids[k].group;
    group.updateMatrixWorld(true);
    const p = new Vector3(...point).applyMatrix4(group.matrixWorld).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  sceneInView() { return this.boxInView(this.sceneBox()); }

  // Solid k: its mesh and spheres, from where the camera looks now.
  frameSolid(k) {
    this.frameBox(this.sceneBox([this.solids[k]]), this.camera.position.clone().sub(this.orbit.target));
  }

  // The largest connected patch of gap triangles (by area) of the solids shown, framed from where
  // the camera looks now, at least `least` of the scene's size across. False when there is none.
  frameGaps(least = 0.05) {
    let best = null;
    for (const solid of this.solids) {
      if (!solid.group.visible) continue;
      const patch = solid.mesh.largestGap();
      if (patch && (!best || patch.area > best.area)) best = { ...patch, solid };
    }
    if (!best) return false;
    best.solid.group.updateMatrixWorld(true);
    const box = best.box.clone().applyMatrix4(best.solid.group.matrixWorld);
    const size = this.sceneBox().getSize(new Vector3()).length() * least;
    box.expandByScalar(Math.max(0, (size - box.getSize(new Vector3()).length()) / 2));
    this.frameBox(box, this.camera.position.clone().sub(this.orbit.target));
    return true;
  }

  // Every mesh and sphere (of the solids given, by default all shown), in the world frame.
  sceneBox(solids = this.solids.filter((s) => s.shown && !s.compareHidden)) {
    const box = new Box3();
    const bounds = new Box3();
    for (const { group, mesh, spheres } of solids) {
      group.updateMatrixWorld(true);
      bounds.copy(mesh.geometry.boundingBox).applyMatrix4(group.matrixWorld);
      box.union(bounds);
      for (const [x, y, z, r] of spheres.spheres) {
        const c = new Vector3(x, y, z).applyMatrix4(group.matrixWorld);
        box.expandByPoint(c.clone().addScalar(r)).expandByPoint(c.clone().addScalar(-r));
      }
    }
    if (box.isEmpty()) box.set(new Vector3(-1, -1, -1), new Vector3(1, 1, 1));
    return box;
  }

  // The camera on `direction` from the box's centre, far enough for its bounding sphere to fit
  // the narrower of the view's two angles.
  frameBox(box, direction) {
    const center = box.getCenter(new Vector3());
    const radius = Math.max(box.getSize(new Vector3()).length() / 2, 1e-6);
    const vertical = (this.camera.fov * Math.PI) / 360;
    const horizontal = Math.atan(Math.tan(vertical) * this.camera.aspect);
    const distance = radius / Math.sin(Math.min(vertical, horizontal)) * 1.05;
    if (direction.lengthSq() === 0) direction.set(1, 1, 1);
    this.camera.position.copy(center).addScaledVector(direction.normalize(), distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.orbit.target.copy(center);
    this.orbit.update();
    this.requestRender();
  }

  // What is under the pointer: the smallest sphere hit (so small spheres inside large ones can be
  // picked), or, with surfaceOnly, the nearest point of a solid's surface in the solid's frame.
  pick(clientX, clientY, { surfaceOnly = false } = {}) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new Vector2(((clientX - rect.left) / rect.width) * 2 - 1,
      -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    if (surfaceOnly) {
      const hits = this.raycaster.intersectObjects(this.drawnMeshes(), false);
      if (!hits.length) return null;
      const solid = hits[0].object.userData.solid;
      const inverse = new Matrix4().copy(this.solids[solid].group.matrixWorld).invert();
      return { solid, point: hits[0].point.clone().applyMatrix4(inverse).toArray() };
    }
    const layers = this.solids.filter((s) => s.group.visible && this.display.spheres)
      .map((s) => s.spheres.mesh).filter((m) => m && m.count > 0);
    let best = null;
    for (const hit of this.raycaster.intersectObjects(layers, false)) {
      const solid = hit.object.userData.solid;
      const r = this.solids[solid].spheres.spheres[hit.instanceId][3];
      if (!best || r < best.r) best = { solid, index: hit.instanceId, r };
    }
    return best;
  }

  // Shows the gizmo on sphere [x,y,z,r] of solid k (null: none).
  select(k, sphere) {
    if (k === null || !sphere) {
      this.gizmo.detach();
      this.handle.removeFromParent();
    } else {
      this.solids[k].group.add(this.handle);
      this.placeHandle(sphere);
      if (this.gizmo.enabled) this.gizmo.attach(this.handle);  // no gizmo on a static page
    }
    this.requestRender();
  }

  placeHandle([x, y, z, r]) {
    this.handle.position.set(x, y, z);
    this.outline.scale.setScalar(Math.max(r, 1e-9) * 1.001);
    this.handle.updateMatrixWorld(true);
  }

  setGizmoEnabled(enabled) { this.gizmo.enabled = enabled; }

  resize() {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  // Every change draws at the next animation frame, one frame however many changes came before
  // it: drawing at once after each change queued frames faster than a software renderer drew
  // them, and the page then stalled for seconds while they drained.
  requestRender() {
    if (this.renderPending) return;
    this.renderPending = true;
    requestAnimationFrame(() => this.renderNow());
  }

  renderNow() {
    this.renderPending = false;
    this.renderer.render(this.scene, this.camera);
  }

  // Resolves once the frame a change asked for has been drawn (its callback runs after the
  // drawing one, which was registered first).
  nextFrame() {
    return new Promise((resolve) => requestAnimationFrame(() => resolve()));
  }

}

// The gizmo's centre handle moves the sphere in the screen's plane, changing all three
// coordinates at once, and lights up whenever the pointer rests at the centre of a selected
// sphere: it is taken out, the axes and planes stay. The handles are found through the
// controls' helper (getHelper), on the child that three.js marks isTransformControlsGizmo.
function dropFreeMoveHandle(gizmo) {
  const parts = gizmo.getHelper().children.find((c) => c.isTransformControlsGizmo);
  if (!parts) return;
  for (const group of [parts.gizmo && parts.gizmo.translate, parts.picker && parts.picker.translate]) {
    if (!group) continue;
    for (const handle of group.children.filter((c) => c.name === 'XYZ')) group.remove(handle);
  }
}
