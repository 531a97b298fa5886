// The side panel: status, certificate, selection, legend, sliders and the message line. Only
// DOM here; what the controls do is app.js's business.
import { rampGradient } from './colors.js';

const $ = (id) => document.getElementById(id);

// The selection's fields, in the order of a sphere's [x, y, z, r].
export const selectionFields = ['sel-x', 'sel-y', 'sel-z', 'sel-r'];

export function element(id) { return $(id); }

// One line, always visible: errors in red until the next message replaces them.
export function showMessage(text, kind = 'info') {
  const line = $('message');
  line.textContent = text;
  line.className = kind;
}

export function setMode({ title, staticMode }) {
  $('title').textContent = title ? `sphereset view: ${title}` : 'sphereset view';
  document.title = $('title').textContent;
  $('mode').textContent = staticMode ? 'static snapshot (editing is off)' : '';
  for (const id of ['edit-tools', 'save', 'sel-hint']) $(id).classList.toggle('hidden', staticMode);
  for (const id of selectionFields) $(id).disabled = staticMode;
  $('legend-bar').style.background = rampGradient();
}

// The formats Save can write (a robot's: every robot format), the scene's own first chosen.
export function showSaveFormats(save) {
  const formats = (save && save.as) || [];
  const select = $('save-format');
  select.classList.toggle('hidden', formats.length < 2);
  select.replaceChildren(...formats.map((f) => {
    const option = document.createElement('option');
    option.value = f.format;
    option.textContent = `as ${f.format}`;
    option.title = f.path;
    return option;
  }));
  if (save) select.value = save.format;
}

// The surface choice, for scenes with a repaired mesh.
export function showSurfaceChoice(any) {
  $('surface-row').classList.toggle('hidden', !any);
}

export function setSelectionEditable(editable) {
  for (const id of selectionFields) $(id).disabled = !editable;
  $('sel-hint').textContent = editable
    ? 'Drag the arrows to move it; Shift + wheel changes the radius.'
    : 'Shown, not edited (a static page, or the compared set).';
}

// The two sets side by side: per set, its spheres, E_r, links covered and largest protrusion.
export function showCompare(names, solids) {
  $('compare-box').classList.remove('hidden');
  const figures = [0, 1].map((set) => {
    const mine = solids.filter((s) => (s.set || 0) === set);
    const c = (s) => s.certificate || {};
    return [
      names[set],
      String(mine.reduce((n, s) => n + s.spheres.length, 0)),
      number(mine.reduce((n, s) => n + (c(s).er_sum || 0), 0)),
      `${mine.filter((s) => c(s).covered).length} of ${mine.length}`,
      number(mine.reduce((m, s) => Math.max(m, Number.isFinite(c(s).protrusion) ? c(s).protrusion : 0), 0), 4),
    ];
  });
  const rows = ['set', 'spheres', 'E_r summed', 'covered', 'protrusion'];
  $('compare-table').replaceChildren(...rows.map((name, r) => {
    const tr = document.createElement('tr');
    for (const text of [name, figures[0][r], figures[1][r]]) {
      const td = document.createElement('td');
      td.textContent = text;
      tr.appendChild(td);
    }
    return tr;
  }));
}

// The whole scene covers when every solid's set covers.
export function showStatus(solids) {
  const covered = solids.length > 0 && solids.every((s) => s.certificate && s.certificate.covered);
  const status = $('status');
  status.textContent = covered ? 'covered' : 'not covered';
  status.className = covered ? 'covered' : 'not-covered';
}

const yesNo = (v) => (v === true ? 'yes' : v === false ? 'no' : 'n/a');
export const number = (v, digits = 6) => (Number.isFinite(v) ? Number(v.toPrecision(digits)).toString() : 'n/a');

export function showCertificate(solids, current, redCounts) {
  const solid = solids[current];
  const c = solid.certificate || {};
  const rows = [
    ['solid', solid.link || solid.name || String(current)],
    ['spheres', String(solid.spheres.length)],
    ['E_r summed', number(c.er_sum)],
    ['surface covered', yesNo(c.surface_covered)],
    ['interior covered', yesNo(c.interior_covered)],
    ['original covered', yesNo(c.original_covered)],
    ['largest gap', Number.isFinite(c.max_gap) ? `${number(c.max_gap, 4)} of the diagonal` : 'n/a'],
    ['protrusion', Number.isFinite(c.protrusion) ? `${number(c.protrusion, 4)} (certified)` : 'n/a'],
    ['gap triangles', String(redCounts[current])],
    ['covered', yesNo(c.covered)],
  ];
  // The edited set's solids (a compared set has its own column in the compare table).
  const edited = solids.filter((s) => s.set !== 1);
  if (edited.length > 1) {
    const total = edited.reduce((sum, s) => sum + (s.certificate ? s.certificate.er_sum : 0), 0);
    const coveredCount = edited.filter((s) => s.certificate && s.certificate.covered).length;
    const worst = edited.reduce((m, s) => Math.max(m, s.certificate && Number.isFinite(s.certificate.protrusion) ? s.certificate.protrusion : 0), 0);
    rows.push(['all solids', `${coveredCount} of ${edited.length} covered, E_r ${number(total)}, protrusion ${number(worst, 4)}`]);
  }
  const table = $('certificate');
  table.replaceChildren(...rows.map(([name, value]) => {
    const tr = document.createElement('tr');
    for (const text of [name, value]) {
      const td = document.createElement('td');
      td.textContent = text;
      tr.appendChild(td);
    }
    return tr;
  }));
}

// The ramp's ends: a fraction from 0 to 1, or outside volumes from 0 to the largest.
export function showLegend(scale, largest) {
  const relative = scale === 'relative';
  $('legend-what').textContent = relative ? 'outside volume' : 'fraction outside';
  $('legend-max').textContent = relative ? number(largest, 3) : '1';
  $('scale').value = relative ? 'relative' : 'absolute';
}

export function showSolidChoice(solids, current, onChange) {
  const select = $('solid');
  $('solid-row').classList.toggle('hidden', solids.length < 2);
  select.replaceChildren(...solids.map((s, k) => {
    const option = document.createElement('option');
    option.value = String(k);
    option.textContent = (s.link || s.name || `solid ${k}`) + (s.set === 1 ? ' [compared]' : '');
    return option;
  }));
  select.value = String(current);
  select.onchange = () => onChange(Number(select.value));
}

// sphere: [x,y,z,r] or null to hide the panel; link: the name of its solid; outside and
// protrusion: its outside volume and certified protrusion bound (undefined while an edit is only
// previewed: shown as n/a until the server certifies it).
export function showSelection(index, sphere, outside, link, protrusion) {
  $('selection').classList.toggle('hidden', !sphere);
  if (!sphere) return;
  $('sel-index').textContent = `#${index}`;
  if (link !== undefined) $('sel-link').textContent = link;
  selectionFields.forEach((id, j) => {
    if (document.activeElement !== $(id)) $(id).value = number(sphere[j], 7);
  });
  $('sel-outside').textContent = number(outside);
  $('sel-protrusion').textContent = Number.isFinite(protrusion) ? `at most ${number(protrusion, 4)}` : 'n/a';
}


export function showLevel(levels, onChange) {
  $('level-row').classList.toggle('hidden', !levels);
  if (!levels) return;
  const slider = $('level');
  slider.max = String(Math.max(0, levels.count - 1));
  slider.value = String(levels.current);
  $('level-value').textContent = `${levels.current} of ${levels.count - 1}`;
  slider.onchange = () => onChange(Number(slider.value));
}

// Sliders for the joints; onInput(name, value) while dragging.
export function buildJoints(joints, onInput, disabled) {
  $('joints-box').classList.toggle('hidden', !joints.length);
  $('joints').replaceChildren(...joints.map((j) => {
    const row = document.createElement('div');
    row.className = 'row';
    const label = document.createElement('label');
    label.textContent = j.name;
    const slider = document.createElement('input');
    slider.type = 'range';
    const [lower, upper] = jointRange(j);
    slider.min = String(lower);
    slider.max = String(upper);
    slider.step = 'any';  // a joint is continuous
    slider.value = String(j.value);
    slider.dataset.joint = j.name;
    slider.disabled = disabled;
    const value = document.createElement('span');
    value.className = 'value';
    value.textContent = number(j.value, 3);
    slider.oninput = () => {
      value.textContent = number(Number(slider.value), 3);
      onInput(j.name, Number(slider.value));
    };
    row.append(label, slider, value);
    return row;
  }));
}

export function showJoints(joints) {
  for (const j of joints) {
    const slider = document.querySelector(`input[data-joint="${CSS.escape(j.name)}"]`);
    if (!slider) continue;
    if (document.activeElement !== slider) slider.value = String(j.value);
    slider.nextSibling.textContent = number(j.value, 3);
  }
}

// Continuous joints have no limits: one turn either way.
function jointRange(j) {
  const finite = Number.isFinite(j.lower) && Number.isFinite(j.upper) && j.upper > j.lower;
  return finite ? [j.lower, j.upper] : [-Math.PI, Math.PI];
}
