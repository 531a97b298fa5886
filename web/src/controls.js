// The mouse, keyboard and buttons: clicks select spheres or (in Add mode) add one on the surface,
// the gizmo drags a centre, Shift + wheel scales a radius, keys delete, undo and redo.
import * as panels from './panels.js';

const $ = (id) => document.getElementById(id);
const quiet = (promise) => { promise.catch(() => {}); };  // the failure is on the message line

export function wireControls(app, container) {
  const viewer = app.viewer;
  wireButtons(app, viewer);
  wirePicking(app, viewer);
  if (app.staticMode) return;
  wireGizmo(app, viewer);
  wireWheel(app, viewer, container);
  wireKeys(app);
  wireSelectionFields(app);
}

function wireButtons(app, viewer) {
  $('bound').onclick = () => quiet(app.bound(app.current));
  $('save').onclick = () => quiet(app.save());
  $('undo').onclick = () => quiet(app.undo());
  $('redo').onclick = () => quiet(app.redo());
  $('delete').onclick = () => deleteSelected(app);
  $('add').onclick = () => setAddMode(app, !app.addMode);
  $('frame').onclick = () => viewer.frame();
  $('png').onclick = () => {
    const link = document.createElement('a');
    link.href = viewer.pngDataUrl();
    link.download = `${app.scene.title || 'sphereset'}.png`;
    link.click();
  };
}

function setAddMode(app, on) {
  app.addMode = on;
  $('add').classList.toggle('active', on);
  panels.showMessage(on ? 'Add: click the surface where the new sphere goes' : '');
}

function deleteSelected(app) {
  const s = app.selection;
  if (!s) {
    panels.showMessage('select a sphere first');
    return;
  }
  app.select(null);
  quiet(app.deleteSphere(s.solid, s.index));
}

// A click is a press and release without moving; a drag turns the view instead.
function wirePicking(app, viewer) {
  const canvas = viewer.renderer.domElement;
  let down = null;
  canvas.addEventListener('pointerdown', (e) => { down = { x: e.clientX, y: e.clientY }; });
  canvas.addEventListener('pointerup', (e) => {
    if (!down || e.button !== 0) return;
    const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
    down = null;
    if (moved > 4 || viewer.gizmo.dragging || viewer.gizmo.axis !== null) return;
    if (app.addMode) {
      const hit = viewer.pick(e.clientX, e.clientY, { surfaceOnly: true });
      if (!hit) return;
      const radius = 0.05 * (app.solid(hit.solid).diagonal || 1);
      setAddMode(app, false);
      const count = app.solid(hit.solid).spheres.length;
      app.addSphere(hit.solid, [...hit.point, radius])
        .then(() => app.select({ solid: hit.solid, index: count })).catch(() => {});
      return;
    }
    const hit = viewer.pick(e.clientX, e.clientY);
    app.select(hit ? { solid: hit.solid, index: hit.index } : null);
  });
}

function wireGizmo(app, viewer) {
  viewer.gizmo.addEventListener('objectChange', () => {
    const s = app.selection;
    const sphere = app.selectedSphere();
    if (!sphere) return;
    const moved = [...viewer.handle.position.toArray(), sphere[3]];
    viewer.solids[s.solid].spheres.preview(s.index, moved);
    panels.showSelection(s.index, moved, undefined);
  });
  viewer.gizmo.addEventListener('dragging-changed', (e) => {
    const s = app.selection;
    const sphere = app.selectedSphere();
    if (e.value || !sphere) return;
    const moved = [...viewer.handle.position.toArray(), sphere[3]];
    if (moved.every((v, j) => v === sphere[j])) return;
    quiet(app.setSphere(s.solid, s.index, moved));
  });
}

// Shift + wheel over the view: the selected sphere's radius, 5% a notch, sent when the wheel
// rests. Caught before the orbit controls, which would zoom.
function wireWheel(app, viewer, container) {
  let pending = null;
  let timer = 0;
  container.addEventListener('wheel', (e) => {
    if (!e.shiftKey || !app.selection) return;
    e.preventDefault();
    e.stopPropagation();
    const s = app.selection;
    const sphere = pending && pending.solid === s.solid && pending.index === s.index
      ? pending.sphere : app.selectedSphere().slice();
    const notch = e.deltaY || e.deltaX;  // some systems turn Shift + wheel into a sideways scroll
    sphere[3] *= notch < 0 ? 1.05 : 1 / 1.05;
    pending = { solid: s.solid, index: s.index, sphere };
    viewer.solids[s.solid].spheres.preview(s.index, sphere);
    viewer.placeHandle(sphere);
    viewer.requestRender();
    panels.showSelection(s.index, sphere, undefined);
    clearTimeout(timer);
    timer = setTimeout(() => {
      const { solid, index, sphere: edited } = pending;
      pending = null;
      quiet(app.setSphere(solid, index, edited));
    }, 300);
  }, { capture: true, passive: false });
}

function wireKeys(app) {
  window.addEventListener('keydown', (e) => {
    const tag = e.target && e.target.tagName;
    if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA') return;
    const ctrl = e.ctrlKey || e.metaKey;
    const key = e.key.toLowerCase();
    if (e.key === 'Delete' || e.key === 'Backspace') {
      e.preventDefault();
      deleteSelected(app);
    } else if (ctrl && key === 'z' && !e.shiftKey) {
      e.preventDefault();
      quiet(app.undo());
    } else if (ctrl && (key === 'y' || (key === 'z' && e.shiftKey))) {
      e.preventDefault();
      quiet(app.redo());
    } else if (key === 'f' && !ctrl) {
      app.viewer.frame();
    } else if (e.key === 'Escape') {
      setAddMode(app, false);
      app.select(null);
    }
  });
}

function wireSelectionFields(app) {
  for (const id of ['sel-x', 'sel-y', 'sel-z', 'sel-r']) {
    $(id).addEventListener('change', () => {
      const s = app.selection;
      if (!s) return;
      const sphere = panels.readSelection();
      if (!sphere.every(Number.isFinite)) {
        panels.showMessage('the centre and radius must be numbers', 'error');
        return;
      }
      quiet(app.setSphere(s.solid, s.index, sphere));
    });
  }
}
