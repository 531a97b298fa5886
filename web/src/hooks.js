// window.sphereset: the page's hooks for tests and scripts (docs/view.md). Every hook that
// talks to the server returns a promise resolved after the page has redrawn.

export function installHooks(app, ready) {
  const copy = (value) => JSON.parse(JSON.stringify(value));
  // A change's promise, resolved once the frame it asked for is drawn.
  const drawn = (promise) => promise.then(async (value) => {
    await app.viewer.nextFrame();
    return value;
  });
  const readyDrawn = drawn(ready);
  readyDrawn.catch(() => {});  // a failure is on the message line already
  window.sphereset = {
    ready: readyDrawn,
    scene: () => copy(app.scene),
    sphereCount: (k) => app.viewer.solids[k].spheres.count,
    setSphere: (k, i, sphere) => drawn(app.setSphere(k, i, sphere)),
    addSphere: (k, sphere) => drawn(app.addSphere(k, sphere)),
    deleteSphere: (k, i) => drawn(app.deleteSphere(k, i)),
    undo: () => drawn(app.undo()),
    redo: () => drawn(app.redo()),
    bound: (k) => drawn(app.bound(k)),
    save: () => app.save(),
    fit: (request) => drawn(app.fitPanel.start(request)),
    setJoint: (name, value) => drawn(app.setJoints({ [name]: value })),
    certificate: (k) => copy(app.solid(k).certificate),
    redTriangles: (k) => app.viewer.solids[k].mesh.redCount,
    linkWorldPosition: (k) => app.viewer.worldOrigin(k),
    setLevel: (k, level) => drawn(app.level(k, level)),
    sceneInView: () => app.viewer.sceneInView(),
    sphereColor: (k, i) => app.viewer.solids[k].spheres.colorOf(i),
    visibility: () => app.viewer.visibility(),
    cameraTarget: () => app.viewer.orbit.target.toArray(),
    gizmoAxis: () => app.viewer.gizmo.axis,
    screenOf: (k, point) => app.viewer.screenOf(k, point),
    selection: () => (app.selection ? { ...app.selection, link: app.solidName(app.selection.solid) } : null),
  };
}
