// The mouse, keyboard and buttons: clicks select spheres or (in Add mode) add one on the surface,
// the gizmo drags a centre, Shift + wheel scales a radius, keys delete, undo and redo.
import { rampStops } from './colors.js';
import * as panels from './panels.js';

const $ = (id) => document.getElementById(id);
const quiet = (promise) => { promise.catch(() => {}); };  // the failure is on the message line

export function wireControls(app, container) {
  const viewer = app.viewer;
  wireButtons(app, viewer);
  wirePicking(app, viewer);
  wireHover(app, viewer);
  wireViewOptions(app);
  wireHelp();
  app.fitPanel.wire();
  if (app.staticMode) return;
  wireGizmo(app, viewer);
  wireWheel(app, viewer, container);
  wireKeys(app);
  wireSelectionFields(app);
}

function wireButtons(app, viewer) {
  $('bound').onclick = () => quiet(app.bound(app.current));
  $('save').onclick = () => quiet(app.save($('save-format').value || undefined));
  $('undo').onclick = () => quiet(app.undo());
  $('redo').onclick = () => quiet(app.redo());
  $('delete').onclick = () => deleteSelected(app);
  $('add').onclick = () => setAddMode(app, !app.addMode);
  $('frame').onclick = () => viewer.frame();
  $('png').onclick = () => {
    const link = document.createElement('a');
    link.href = pagePicture(app);
    link.download = `${app.scene.title || 'sphereset'}.png`;
    link.click();
  };
}

function wireViewOptions(app) {
  const viewer = app.viewer;
  $('scale').onchange = () => app.setColorScale($('scale').value);
  $('show-mesh').onchange = () => viewer.setDisplay({ mesh: $('show-mesh').checked });
  $('show-spheres').onchange = () => viewer.setDisplay({ spheres: $('show-spheres').checked });
  $('wireframe').onchange = () => viewer.setDisplay({ wireframe: $('wireframe').checked });
  $('opacity').oninput = () => {
    const opacity = Number($('opacity').value);
    $('opacity-value').textContent = opacity.toFixed(2);
    viewer.setDisplay({ opacity });
  };
  $('surface').onchange = () => quiet(app.setSurface($('surface').value).catch((e) => {
    panels.showMessage(e.message || String(e), 'error');
    throw e;
  }));
  $('frame-gaps').onclick = () => {
    if (!viewer.frameGaps()) panels.showMessage('no gaps: every shown link is covered');
  };
  $('filter').oninput = () => app.refresh();
  $('compare-layout').onchange = () => {
    app.viewer.setCompareLayout($('compare-layout').value);
    app.drawCollisions();
    app.viewer.frame();
  };
  $('auto-frame').onchange = () => {
    app.autoFrame = $('auto-frame').checked;
    if (app.autoFrame) app.viewer.keepInView();
  };
}

// The "?" overlay: the button, the ? key, Escape and its Close button.
function wireHelp() {
  const toggle = (show) => $('help').classList.toggle('hidden', show === undefined ? undefined : !show);
  $('help-button').onclick = () => toggle();
  $('help-close').onclick = () => toggle(false);
  window.addEventListener('keydown', (e) => {
    const tag = e.target && e.target.tagName;
    if (tag === 'INPUT' || tag === 'SELECT' || tag === 'TEXTAREA') return;
    if (e.key === '?') toggle();
    else if (e.key === 'Escape') toggle(false);
  });
}

// The picture of the page's state: a band with the title, the status, the colour legend and
// the certificate's figures of the solid shown, above the view.
export function pagePicture(app) {
  const view = app.viewer.renderer.domElement;
  app.viewer.renderNow();
  const ratio = view.width / Math.max(1, view.clientWidth || view.width);
  const band = Math.round(64 * ratio);
  const canvas = document.createElement('canvas');
  canvas.width = view.width;
  canvas.height = view.height + band;
  const g = canvas.getContext('2d');
  g.fillStyle = '#ffffff';
  g.fillRect(0, 0, canvas.width, band);
  g.drawImage(view, 0, band);
  const pad = 8 * ratio;
  g.font = `bold ${14 * ratio}px system-ui, sans-serif`;
  g.fillStyle = '#222';
  g.textBaseline = 'top';
  g.fillText($('title').textContent, pad, pad);
  const status = $('status');
  const covered = status.classList.contains('covered');
  g.font = `bold ${13 * ratio}px system-ui, sans-serif`;
  const statusWidth = g.measureText(status.textContent).width + 2 * pad;
  const statusX = canvas.width - statusWidth - pad;
  g.fillStyle = covered ? '#d7f5d7' : '#fbd5d5';
  g.fillRect(statusX, pad, statusWidth, 20 * ratio);
  g.fillStyle = covered ? '#165a16' : '#9a1111';
  g.fillText(status.textContent, statusX + pad, pad + 3 * ratio);
  g.font = `${12 * ratio}px system-ui, sans-serif`;
  g.fillStyle = '#333';
  const rows = [...$('certificate').querySelectorAll('tr')].map((tr) => [...tr.children].map((td) => td.textContent));
  const figure = (name) => (rows.find((r) => r[0] === name) || [name, 'n/a'])[1];
  g.fillText(`${figure('solid')}: ${figure('spheres')} spheres, E_r ${figure('E_r summed')}, ` +
    `protrusion ${figure('protrusion')}, gap triangles ${figure('gap triangles')}`, pad, pad + 22 * ratio);
  // The legend: the ramp and its ends.
  const legendX = pad;
  const legendY = pad + 40 * ratio;
  const legendWidth = Math.min(260 * ratio, canvas.width / 2);
  const gradient = g.createLinearGradient(legendX, 0, legendX + legendWidth, 0);
  for (const [t, c] of rampStops()) gradient.addColorStop(t, c);
  g.fillStyle = gradient;
  g.fillRect(legendX, legendY, legendWidth, 8 * ratio);
  g.fillStyle = '#333';
  g.fillText(`0  ${$('legend-what').textContent}  ${$('legend-max').textContent}`, legendX + legendWidth + pad, legendY - 2 * ratio);
  return canvas.toDataURL('image/png');
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

// The name of the link under the pointer, beside it (robots), once the pointer rests: a ray
// through a large mesh at every move would cost more than the move.
const hoverRestMs = 120;
function wireHover(app, viewer) {
  if (app.scene.kind !== 'robot') return;
  const canvas = viewer.renderer.domElement;
  const tip = $('hover');
  let timer = 0;
  canvas.addEventListener('pointermove', (e) => {
    tip.classList.add('hidden');
    clearTimeout(timer);
    if (e.buttons) return;  // turning or dragging
    const x = e.clientX;
    const y = e.clientY;
    timer = setTimeout(() => {
      const hit = viewer.pick(x, y) || viewer.pick(x, y, { surfaceOnly: true });
      tip.classList.toggle('hidden', !hit);
      if (!hit) return;
      tip.textContent = app.solidName(hit.solid);
      tip.style.left = `${x + 12}px`;
      tip.style.top = `${y + 12}px`;
    }, hoverRestMs);
  });
  canvas.addEventListener('pointerleave', () => {
    clearTimeout(timer);
    tip.classList.add('hidden');
  });
}

// A drag of the gizmo changes only the coordinates of the handle it holds ('X', 'XY', ...; the
// gizmo's axes are the solid's own): the others are sent as they were, not as a round trip
// through the link's pose left them.
function wireGizmo(app, viewer) {
  let axis = null;
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
    if (e.value) axis = viewer.gizmo.axis || '';
    if (e.value || !sphere) return;
    const position = viewer.handle.position.toArray();
    const moved = sphere.map((v, j) => (j < 3 && axis.includes('XYZ'[j]) ? position[j] : v));
    if (moved.every((v, j) => v === sphere[j])) {
      viewer.placeHandle(sphere);
      return;
    }
    quiet(app.setSphere(s.solid, s.index, moved));
  });
}

// Shift + wheel over the view: the selected sphere's radius, 5% a notch, sent when the wheel
// rests. Caught before the orbit controls, which would zoom. The wheel owns the radius only: the
// centre is the set's when the edit runs (app.setCoordinate), so a move queued meanwhile stays. A
// notch turned after a rest but before the server's answer starts from the radius sent (no notch
// is lost to a slow answer), an answer that comes while more notches wait shows them again, and
// any other request (a notch on another sphere, Delete, Ctrl+Z, ...) first sends the notches
// waiting (app.heldBack).
function wireWheel(app, viewer, container) {
  let pending = null;  // { solid, index, radius, sent }
  let timer = 0;
  const show = (p) => {
    const held = app.solid(p.solid).spheres[p.index];
    if (!held) return;
    const sphere = [held[0], held[1], held[2], p.radius];
    viewer.solids[p.solid].spheres.preview(p.index, sphere);
    const s = app.selection;
    if (s && s.solid === p.solid && s.index === p.index) {
      viewer.placeHandle(sphere);
      panels.showSelection(p.index, sphere, undefined);
    }
    viewer.requestRender();
  };
  const send = () => {
    clearTimeout(timer);
    const p = pending;
    if (!p || p.sent) return;
    p.sent = true;
    const request = app.setCoordinate(p.solid, p.index, 3, p.radius);
    quiet(request);
    const answered = () => {
      if (pending === p) pending = null;
      else if (pending) show(pending);  // later notches, drawn again over the answer
    };
    request.then(answered, answered);
  };
  app.heldBack.push(send);
  container.addEventListener('wheel', (e) => {
    if (!e.shiftKey || !app.selection) return;
    e.preventDefault();
    e.stopPropagation();
    const s = app.selection;
    const same = pending && pending.solid === s.solid && pending.index === s.index;
    if (pending && !same) send();  // app.run would too; before `pending` is replaced
    const notch = e.deltaY || e.deltaX;  // some systems turn Shift + wheel into a sideways scroll
    const from = same ? pending.radius : app.selectedSphere()[3];
    const radius = from * (notch < 0 ? 1.05 : 1 / 1.05);
    pending = { solid: s.solid, index: s.index, radius, sent: false };
    viewer.gizmo.axis = null;  // no handle lights up under a pointer that only turns the wheel
    show(pending);
    clearTimeout(timer);
    timer = setTimeout(send, 300);
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
      if (app.addMode) setAddMode(app, false);
      app.select(null);
    }
  });
}

// A field changes its own coordinate only: the others are sent as the set holds them when the
// edit runs, never as the fields show them (rounded to 7 digits).
function wireSelectionFields(app) {
  panels.selectionFields.forEach((id, j) => {
    $(id).addEventListener('change', () => {
      const s = app.selection;
      const sphere = app.selectedSphere();
      if (!s || !sphere) return;
      const text = $(id).value.trim();
      const value = Number(text);
      if (text === '' || !Number.isFinite(value)) {
        panels.showMessage(`${id === 'sel-r' ? 'the radius' : 'a centre coordinate'} must be a number`, 'error');
        return;
      }
      if (value === sphere[j]) return;
      quiet(app.setCoordinate(s.solid, s.index, j, value));
    });
  });
}
