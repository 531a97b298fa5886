// window.sphereset: the page's hooks for tests and scripts (docs/view.md). Every hook that
// talks to the server returns a promise resolved after the page has redrawn.

export function installHooks(app, ready) {
  const copy = (value) => JSON.parse(JSON.stringify(value));
  window.sphereset = {
    ready,
    scene: () => copy(app.scene),
    sphereCount: (k) => app.viewer.solids[k].spheres.count,
    setSphere: (k, i, sphere) => app.setSphere(k, i, sphere),
    addSphere: (k, sphere) => app.addSphere(k, sphere),
    deleteSphere: (k, i) => app.deleteSphere(k, i),
    undo: () => app.undo(),
    redo: () => app.redo(),
    bound: (k) => app.bound(k),
    save: () => app.save(),
    fit: (request) => app.fitPanel.start(request),
    setJoint: (name, value) => app.setJoints({ [name]: value }),
    certificate: (k) => copy(app.solid(k).certificate),
    redTriangles: (k) => app.viewer.solids[k].mesh.redCount,
    linkWorldPosition: (k) => app.viewer.worldOrigin(k),
    setLevel: (k, level) => app.level(k, level),
    sceneInView: () => app.viewer.sceneInView(),
    sphereColor: (k, i) => app.viewer.solids[k].spheres.colorOf(i),
    visibility: () => app.viewer.visibility(),
    cameraTarget: () => app.viewer.orbit.target.toArray(),
    gizmoAxis: () => app.viewer.gizmo.axis,
    screenOf: (k, point) => app.viewer.screenOf(k, point),
    selection: () => (app.selection ? { ...app.selection, link: app.solidName(app.selection.solid) } : null),
  };
}
