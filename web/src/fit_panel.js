// Fits started from the page (docs/view.md, POST /api/fit): one link (or the mesh) with a count
// and a quality, or with the fewest spheres within a max protrusion, or, for a robot, every link
// within a budget, a max protrusion, or both. The server fits in a thread of its
// own; the page asks how far it is every `pollMs` and shows a progress bar with Cancel; the
// finished sets come back with their certificates, and Ctrl+Z undoes a fit like any change (a
// robot's fit in one step, every link at once).
import { replaceEdits } from './history.js';
import * as panels from './panels.js';

const $ = (id) => document.getElementById(id);
const pollMs = 150;
const pollFailures = 20;  // questions in a row that may fail (a busy server answers 503) before the page gives up

export class FitPanel {
  constructor(app) {
    this.app = app;
    this.running = false;
  }

  wire() {
    const app = this.app;
    $('fit-box').classList.toggle('hidden', app.staticMode);
    if (app.staticMode) return;
    const robot = app.scene.kind === 'robot';
    $('fit-what').textContent = robot ? 'this link' : 'the mesh';
    // The qualities the library takes, as the scene names them (its default chosen).
    const { qualities, quality } = app.scene.fit;
    $('fit-quality').replaceChildren(...qualities.map((q) => new Option(q, q, q === quality, q === quality)));
    $('budget-row').classList.toggle('hidden', !robot);
    const edited = app.scene.solids.filter((s) => s.set !== 1);
    if (robot) $('fit-budget').value = String(edited.reduce((n, s) => n + s.spheres.length, 0));
    $('fit').onclick = () => this.start(this.solidRequest()).catch(() => {});
    $('fit-robot').onclick = () => this.start(this.robotRequest()).catch(() => {});
    $('fit-cancel').onclick = () => { app.api.fitCancel().catch((e) => panels.showMessage(e.message, 'error')); };
  }

  // The max protrusion typed (a length or "P%"; the server's table checks it), or none.
  tolerance() {
    const text = $('fit-tolerance').value.trim();
    return text === '' ? undefined : text;
  }

  // The shown solid: the fewest spheres within the max protrusion when one is typed, else the count.
  solidRequest() {
    const limit = this.tolerance();
    return limit === undefined ? { solid: this.app.current, spheres: Number($('fit-spheres').value) }
      : { solid: this.app.current, max_protrusion: limit };
  }

  // Every link: within the budget, each held to the max protrusion when one is typed (an empty
  // budget with one: each link its fewest within it).
  robotRequest() {
    const limit = this.tolerance();
    const budget = $('fit-budget').value.trim();
    const request = budget === '' && limit !== undefined ? { robot: true } : { budget: Number(budget) };
    if (limit !== undefined) request.max_protrusion = limit;
    return request;
  }

  // Starts a fit and resolves with its last status once it has ended (done, cancelled, failed).
  async start(request) {
    const app = this.app;
    if (this.running) throw new Error('a fit is running');
    const body = { ...request, quality: $('fit-quality').value };
    // The counts are checked by the server (startViewFit), which says what is wrong.
    const before = app.scene.solids.map((s) => s.spheres.map((x) => x.slice()));
    await app.run(() => app.api.fit(body));
    this.running = true;
    this.show(true, 0, 'starting');
    try {
      for (let failures = 0; ;) {
        await new Promise((resolve) => setTimeout(resolve, pollMs));
        let status;
        try {
          status = await app.api.fitStatus();
          failures = 0;
        } catch (e) {
          if (++failures >= pollFailures) throw e;
          continue;
        }
        this.show(true, status.fraction, status.stage);
        if (status.state === 'running') continue;
        await app.run(() => this.finish(status, before, body));
        return status;
      }
    } finally {
      this.running = false;
      this.show(false);
    }
  }

  // The finished fit: its sets applied (each undoable), or what stopped it.
  finish(status, before, body) {
    const app = this.app;
    if (status.state === 'cancelled') {
      panels.showMessage('fit cancelled: nothing changed');
      return;
    }
    if (status.state === 'failed') {
      panels.showMessage(`fit failed: ${status.error}`, 'error');
      throw new Error(status.error);
    }
    if (!status.applied || !status.sets) {
      // Applied by another page's question: the scene holds the sets.
      panels.showMessage('fit done elsewhere: reload the page to see it');
      return;
    }
    // A selection on a refitted solid would name another sphere now.
    if (app.selection && status.solids.includes(app.selection.solid)) app.select(null);
    // One step for the whole fit: Ctrl+Z gives every solid it refitted back at once.
    const undo = [];
    status.solids.forEach((k, i) => {
      if (app.applySet(k, status.sets[i])) undo.push({ solid: k, edits: replaceEdits(status.sets[i].spheres, before[k]) });
    });
    app.history.recordParts(undo);
    const split = Object.entries(status.counts).map(([link, n]) => `${link} ${n}`).join(', ');
    const missed = status.tolerance && !status.tolerance_met;
    const limit = body.max_protrusion !== undefined
      ? `max protrusion ${body.max_protrusion} ${missed ? 'NOT met: the best found, ' : 'met: '}` : '';
    if (body.budget !== undefined) {
      panels.showMessage(`budget ${body.budget}: ${limit}${split}`, missed ? 'error' : 'info');
    } else if (body.robot) {
      panels.showMessage(`${limit}${split}`, missed ? 'error' : 'info');
    } else if (limit) {
      const n = Object.values(status.counts)[0];
      panels.showMessage(`${limit}${n} spheres (${body.quality})`, missed ? 'error' : 'info');
    } else {
      panels.showMessage(`fitted ${body.spheres} spheres (${body.quality})`, 'info');
    }
    app.refresh();
  }

  show(visible, fraction = 0, stage = '') {
    $('fit-progress').classList.toggle('hidden', !visible);
    $('fit-bar').value = Number.isFinite(fraction) ? fraction : 0;
    $('fit-stage').textContent = stage || '';
    $('fit').disabled = visible;
    $('fit-robot').disabled = visible;
  }
}
