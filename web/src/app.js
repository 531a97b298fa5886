// The page's state and what its controls do. The scene JSON (docs/view.md) is the state; it
// changes only by the server's answers, which are applied one at a time and in order, and an
// answer older than the newest seen is dropped.
import { sphereShade } from './colors.js';
import { base64ToArrayBuffer, decodeGeometry } from './geometry.js';
import { History, differenceEdits, inverseEdits } from './history.js';
import { jointValues, solidPoses } from './kinematics.js';
import { contactSegments, showCollisions } from './collisions.js';
import { FitPanel } from './fit_panel.js';
import { showLinkList } from './link_list.js';
import * as panels from './panels.js';
import { Viewer } from './viewer.js';

export class App {
  // api: a ServerApi, or null for a static snapshot (staticScene then holds the scene).
  constructor({ api, staticScene }) {
    this.api = api;
    this.staticScene = staticScene;
    this.staticMode = !api;
    this.scene = null;
    this.viewer = null;
    this.history = new History();
    this.selection = null;  // { solid, index }
    this.current = 0;       // the solid the certificate panel shows
    this.newestVersion = -Infinity;
    this.queue = Promise.resolve();
    this.heldBack = [];  // functions that send an edit the page holds back (the wheel's radius)
    this.redCounts = [];
    this.addMode = false;
    this.colorScale = 'absolute';  // colors.js: 'absolute' or 'relative'
    this.autoFrame = true;         // robots: frame the robot after a joint moves it
    this.shown = [];               // per solid: false when hidden
    this.fitPanel = new FitPanel(this);
  }

  async start(container) {
    let scene;
    let geometries;
    if (this.staticMode) {
      scene = this.staticScene;
      geometries = scene.solids.map((s, k) => {
        if (typeof s.geometry !== 'string') throw new Error(`solid ${k}: the snapshot has no geometry`);
        const geometry = decodeGeometry(base64ToArrayBuffer(s.geometry));
        delete s.geometry;  // decoded once; scene() stays small
        return geometry;
      });
    } else {
      scene = await this.api.scene();
      geometries = await Promise.all(scene.solids.map((_, k) => this.api.geometry(k)));
    }
    this.scene = scene;
    this.jointInput = Object.fromEntries((scene.joints || []).map((j) => [j.name, j.value]));
    this.newestVersion = Number.isFinite(scene.version) ? scene.version : -Infinity;
    this.viewer = new Viewer(container, { zUp: scene.kind === 'robot' });
    this.viewer.build(geometries, scene.poses, scene.solids.map((s) => s.set || 0));
    if (this.comparing) this.viewer.setCompareLayout('overlaid');
    this.viewer.setGizmoEnabled(!this.staticMode);
    panels.setMode({ title: scene.title, staticMode: this.staticMode });
    panels.showSurfaceChoice(scene.solids.some((s) => s.repaired));
    panels.showSaveFormats(scene.save);
    panels.showSolidChoice(scene.solids, this.current, (k) => this.showSolid(k));
    // A static page poses its robot itself when it carries the joint tree.
    const posable = !this.staticMode || Boolean(scene.kinematics);
    panels.buildJoints(scene.joints || [], (name, value) => this.dragJoint(name, value), !posable);
    this.redrawAll();
    this.viewer.frame();
    this.viewer.renderNow();
  }

  // Runs fn after every earlier request has been answered; a failure is shown and rethrown. An
  // edit held back (heldBack) is sent first, so requests run in the order the user made them.
  run(fn) {
    for (const send of this.heldBack) send();
    const result = this.queue.then(fn);
    this.queue = result.catch(() => {});
    return result.catch((e) => {
      panels.showMessage(e.message || String(e), 'error');
      throw e;
    });
  }

  requireServer() {
    if (this.staticMode) throw new Error('static snapshot: editing is off');
  }

  // True when the answer is current; an older one is dropped.
  accept(answer) {
    if (!answer || !Number.isFinite(answer.version)) return true;
    if (answer.version < this.newestVersion) return false;
    this.newestVersion = answer.version;
    this.scene.version = answer.version;
    return true;
  }

  applySet(k, answer) {
    if (!this.accept(answer)) return false;
    const solid = this.scene.solids[k];
    solid.spheres = answer.spheres;
    solid.certificate = answer.certificate;
    if (answer.collisions !== undefined) this.scene.collisions = answer.collisions;
    if (answer.levels !== undefined) solid.levels = answer.levels;
    this.redrawAll();
    return true;
  }

  // --- edits ------------------------------------------------------------------------------

  // edits: a list, or a function that makes it from the set as it is when the edit runs (after
  // every earlier request).
  edit(k, edits) {
    return this.run(async () => {
      this.requireServer();
      const before = this.solid(k).spheres;
      const list = typeof edits === 'function' ? edits() : edits;
      const answer = await this.api.edit(k, list);
      if (this.applySet(k, answer)) this.history.record(k, inverseEdits(before, list));
      panels.showMessage('');
      this.refresh();
      return answer;
    });
  }

  setSphere(k, i, sphere) { return this.edit(k, [{ op: 'set', index: i, sphere }]); }
  // One coordinate of a sphere (0-2 the centre's, 3 the radius): the others are the set's when
  // the edit runs, so an edit queued before it stays.
  setCoordinate(k, i, j, value) {
    return this.edit(k, () => {
      const held = this.solid(k).spheres[i];
      if (!held) throw new Error(`sphere ${i} is no longer in the set`);
      const sphere = held.slice();
      sphere[j] = value;
      return [{ op: 'set', index: i, sphere }];
    });
  }
  addSphere(k, sphere) { return this.edit(k, [{ op: 'add', sphere }]); }
  deleteSphere(k, i) { return this.edit(k, [{ op: 'delete', index: i }]); }

  undo() { return this.step('undo'); }
  redo() { return this.step('redo'); }

  // Applies the last undo (or redo) step, part by part, and files its opposite on the other
  // stack. The stacks are looked up when the step runs, not when its key was pressed: a change
  // queued before it (a fit, a level) may have recorded or forgotten steps. A part the server
  // refuses stays, with the parts after it; the parts applied are filed as their own step.
  step(what) {
    return this.run(async () => {
      this.requireServer();
      const h = this.history;
      const [from, to] = what === 'undo' ? [h.undoSteps, h.redoSteps] : [h.redoSteps, h.undoSteps];
      const step = from.pop();
      if (!step) {
        panels.showMessage(`nothing to ${what}`);
        return null;
      }
      const opposite = [];
      let answer = null;
      const file = () => { if (opposite.length) to.push({ parts: opposite }); };
      for (let i = 0; i < step.parts.length; i++) {
        const part = step.parts[i];
        const before = this.solid(part.solid).spheres;
        try {
          answer = await this.api.edit(part.solid, part.edits);
        } catch (e) {
          from.push({ parts: step.parts.slice(i) });
          file();
          this.refresh();
          throw e;
        }
        if (this.applySet(part.solid, answer)) {
          opposite.push({ solid: part.solid, edits: inverseEdits(before, part.edits) });
        }
      }
      file();
      panels.showMessage('');
      this.refresh();
      return answer;
    });
  }

  bound(k) {
    return this.run(async () => {
      this.requireServer();
      const before = this.solid(k).spheres;
      const answer = await this.api.bound(k);
      if (this.applySet(k, answer)) {
        const back = differenceEdits(answer.spheres, before);
        if (back) this.history.record(k, back);
        else this.history.forget(k);
      }
      this.refresh();
      panels.showMessage(`bound: ${answer.certificate && answer.certificate.covered ? 'covered' : 'not covered'}`);
      return answer;
    });
  }

  // A tree's level: from the server, or on a static page from the levels it carries (a level
  // change is not an edit).
  level(k, level) {
    return this.run(async () => {
      const answer = this.staticMode ? this.staticLevel(k, level) : await this.api.level(k, level);
      if (this.selection && this.selection.solid === k) this.select(null);
      if (this.applySet(k, answer)) {
        this.history.forget(k);
        // The answer is the level's set; which level it is, the page knows from its request.
        const levels = this.solid(k).levels;
        if (levels && answer.levels === undefined) levels.current = level;
      }
      this.refresh();
      return answer;
    });
  }

  staticLevel(k, level) {
    const sets = this.solid(k).level_sets;
    if (!Array.isArray(sets)) throw new Error('this static page holds one level only');
    if (!Number.isInteger(level) || level < 0 || level >= sets.length) {
      throw new Error(`level ${level} is not a level of this tree (0 to ${sets.length - 1})`);
    }
    return { spheres: sets[level].spheres, certificate: sets[level].certificate };
  }

  setJoints(joints) {
    return this.run(() => this.pose(joints));
  }

  // The robot posed by the server, or on a static page by its own kinematics.
  async pose(joints) {
    const answer = this.staticMode ? this.staticPose(joints) : await this.api.pose(joints);
    if (this.accept(answer)) {
      this.scene.poses = answer.poses;
      this.scene.joints = answer.joints;
      if (answer.collisions !== undefined) this.scene.collisions = answer.collisions;
      else if (this.staticMode) this.collisionsStale = true;
      this.viewer.setPoses(answer.poses);
      this.drawCollisions();
      if (this.autoFrame) this.viewer.keepInView();
      panels.showJoints(answer.joints);
      this.viewer.requestRender();
    }
    return answer;
  }

  staticPose(joints) {
    const kinematics = this.scene.kinematics;
    if (!kinematics) throw new Error('static snapshot: this page cannot pose its robot');
    for (const [name, value] of Object.entries(joints)) {
      if (!this.scene.joints.some((j) => j.name === name)) throw new Error(`no joint '${name}'`);
      if (!Number.isFinite(value)) throw new Error(`joint '${name}': ${value} is not a number`);
    }
    this.jointInput = { ...this.jointInput, ...joints };
    const values = jointValues(kinematics, this.jointInput);
    return {
      poses: solidPoses(kinematics, this.scene.solids, values),
      joints: this.scene.joints.map((j) => ({ ...j, value: values[j.name] })),
    };
  }

  // A slider being dragged: one request at a time, with the latest values.
  dragJoint(name, value) {
    this.jointDraft = { ...this.jointDraft, [name]: value };
    if (this.jointQueued) return;
    this.jointQueued = true;
    this.run(() => {
      this.jointQueued = false;
      const joints = this.jointDraft;
      this.jointDraft = {};
      return this.pose(joints);
    }).catch(() => {});
  }

  // format: one of the scene's save.as formats, or undefined for its own.
  save(format) {
    return this.run(async () => {
      this.requireServer();
      const own = this.scene.save && this.scene.save.format;
      const answer = await this.api.save(format && format !== own ? format : undefined);
      panels.showMessage(`saved ${answer.path} (${answer.bytes} bytes)`, 'info');
      return answer;
    });
  }

  // --- selection --------------------------------------------------------------------------

  // The certificate panel shows solid k; a selection on another solid is dropped (its gizmo and
  // fields would otherwise stand under the new solid's certificate).
  showSolid(k) {
    this.current = k;
    if (this.selection && this.selection.solid !== k) this.select(null);
    else this.refresh();
  }

  select(selection) {
    this.selection = selection;
    if (selection) this.current = selection.solid;
    this.showSelection();
    this.refresh();
  }

  selectedSphere() {
    const s = this.selection;
    return s ? this.solid(s.solid).spheres[s.index] : null;
  }

  showSelection() {
    const s = this.selection;
    const sphere = this.selectedSphere();
    if (s && !sphere) this.selection = null;  // deleted, or the set got shorter
    if (!this.selection) {
      this.viewer.select(null);
      panels.showSelection(null, null);
      return;
    }
    const solid = this.solid(s.solid);
    const certificate = solid.certificate || {};
    const outside = certificate.outside_volume || [];
    const protrusion = certificate.sphere_protrusion || [];
    this.viewer.setGizmoEnabled(this.editable(s.solid));
    panels.setSelectionEditable(this.editable(s.solid));
    this.viewer.select(s.solid, sphere);
    panels.showSelection(s.index, sphere, outside[s.index], this.solidName(s.solid),
      protrusion[s.index]);
  }

  // --- what is shown ----------------------------------------------------------------------

  setShown(k, shown) {
    this.shown[k] = shown;
    this.viewer.setSolidShown(k, shown);
    if (!shown && this.selection && this.selection.solid === k) this.select(null);
    else this.refresh();
  }

  // 'displayed' (a repaired mesh's original triangles) or 'repaired' (its solid), fetched once.
  async setSurface(surface) {
    if (surface === 'repaired') {
      const solids = this.scene.solids;
      for (let k = 0; k < solids.length; k++) {
        if (!solids[k].repaired || this.viewer.solids[k].repaired) continue;
        const geometry = this.staticMode
          ? decodeGeometry(base64ToArrayBuffer(solids[k].repaired_geometry || ''))
          : await this.api.geometry(k, 'repaired');
        this.viewer.setRepairedGeometry(k, geometry);
      }
    }
    this.viewer.setDisplay({ surface });
  }

  // What the page calls solid k: its link, else its name; a compared set's with its file.
  solidName(k) {
    const solid = this.solid(k);
    const name = solid.link || solid.name || `solid ${k}`;
    return solid.set === 1 ? `${name} [${this.scene.sets[1]}]` : name;
  }

  // Whether a second set is shown for comparison (docs/view.md, "sets").
  get comparing() { return Array.isArray(this.scene.sets) && this.scene.sets.length > 1; }

  // Whether solid k's set can change (not a static page, not the compared set).
  editable(k) { return !this.staticMode && this.solid(k).set !== 1; }

  // --- drawing ----------------------------------------------------------------------------

  solid(k) {
    const solid = this.scene && this.scene.solids[k];
    if (!solid) throw new Error(`no solid ${k}`);
    return solid;
  }

  // Every solid's spheres on one colour scale, the gap triangles, the panels.
  redrawAll() {
    const solids = this.scene.solids;
    let largest = 0;
    for (const s of solids) {
      for (const v of (s.certificate && s.certificate.outside_volume) || []) {
        if (Number.isFinite(v)) largest = Math.max(largest, v);
      }
    }
    solids.forEach((s, k) => {
      const c = s.certificate || {};
      const outside = c.outside_volume || [];
      const shades = s.spheres.map((sphere, i) => sphereShade(sphere, outside[i], this.colorScale, largest));
      const layer = this.viewer.solids[k];
      layer.spheres.update(s.spheres, shades);
      this.redCounts[k] = layer.mesh.setUncovered(c.uncovered_triangles);
    });
    panels.showLegend(this.colorScale, largest);
    this.drawCollisions();
    this.showSelection();
    this.refresh();
  }

  // The self-collision list and its segments.
  drawCollisions() {
    showCollisions(this.scene.collisions || null, Boolean(this.collisionsStale));
    this.viewer.setContactSegments(this.collisionsStale ? [] : contactSegments(this.scene, this.viewer));
  }

  setColorScale(scale) {
    this.colorScale = scale === 'relative' ? 'relative' : 'absolute';
    this.redrawAll();
  }

  refresh() {
    const solids = this.scene.solids;
    // The status is the edited set's; the compare table holds both.
    panels.showStatus(solids.filter((x) => x.set !== 1));
    if (this.comparing) panels.showCompare(this.scene.sets, solids);
    panels.showCertificate(solids, this.current, this.redCounts);
    // A compared tree's level is not changed (the server refuses it): no slider for it.
    const levels = this.editable(this.current) || this.staticMode ? solids[this.current].levels : null;
    panels.showLevel(levels, (l) => this.level(this.current, l).catch(() => {}));
    document.getElementById('solid').value = String(this.current);
    const names = solids.map((_, k) => this.solidName(k));
    showLinkList(solids, { current: this.current, selection: this.selection, shown: this.shown, names }, {
      showLink: (k) => this.showSolid(k),
      frameLink: (k) => this.viewer.frameSolid(k),
      selectSphere: (k, i) => this.select({ solid: k, index: i }),
      setShown: (k, shown) => this.setShown(k, shown),
    });
    document.getElementById('undo').disabled = !this.history.canUndo;
    document.getElementById('redo').disabled = !this.history.canRedo;
    this.viewer.requestRender();
  }
}
