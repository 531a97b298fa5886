// The list of links (a mesh's one solid, or a robot's links): each with a show/hide box, its
// sphere count, E_r and a coverage mark; the solid shown lists its spheres (index, radius,
// fraction outside). Clicking a link shows and frames it; clicking a sphere selects it; the
// filter keeps the links whose name holds its text. Only DOM here.

import { fractionOutside } from './colors.js';
import { number } from './panels.js';

const $ = (id) => document.getElementById(id);
const maxSphereRows = 500;  // a set of thousands of spheres lists its first rows only

// solids: the scene's; state: { current, selection, shown[], names[] }; on: { showLink(k), frameLink(k),
// selectSphere(k, i), setShown(k, shown) }.
export function showLinkList(solids, state, on) {
  $('list-title').textContent = solids.length > 1 ? 'Links' : 'Spheres';
  $('filter').classList.toggle('hidden', solids.length < 2);
  const filter = $('filter').value.trim().toLowerCase();
  const rows = [];
  solids.forEach((solid, k) => {
    const name = state.names[k];
    if (filter && !name.toLowerCase().includes(filter)) return;
    rows.push(linkRow(solid, k, name, state, on));
    if (k === state.current) rows.push(...sphereRows(solid, k, state, on));
  });
  $('link-list').replaceChildren(...rows);
}

function linkRow(solid, k, name, state, on) {
  const c = solid.certificate || {};
  const row = document.createElement('div');
  row.className = `link${k === state.current ? ' current' : ''}`;
  row.dataset.solid = String(k);
  const box = document.createElement('input');
  box.type = 'checkbox';
  box.checked = state.shown[k] !== false;
  box.title = `show ${name}`;
  box.onclick = (e) => {
    e.stopPropagation();
    on.setShown(k, box.checked);
  };
  const label = document.createElement('span');
  label.className = 'name';
  label.textContent = name;
  const figures = document.createElement('span');
  figures.className = 'figures';
  figures.textContent = `${solid.spheres.length} · E_r ${number(c.er_sum, 3)}`;
  const mark = document.createElement('span');
  mark.className = `mark ${c.covered ? 'yes' : 'no'}`;
  mark.textContent = c.covered ? '✓' : '✗';
  mark.title = c.covered ? 'covered' : 'not covered';
  row.append(box, label, figures, mark);
  row.onclick = () => {
    on.showLink(k);
    on.frameLink(k);
  };
  return row;
}

function sphereRows(solid, k, state, on) {
  const outside = (solid.certificate && solid.certificate.outside_volume) || [];
  const rows = solid.spheres.slice(0, maxSphereRows).map((s, i) => {
    const row = document.createElement('div');
    const selected = state.selection && state.selection.solid === k && state.selection.index === i;
    row.className = `sphere${selected ? ' selected' : ''}`;
    row.dataset.solid = String(k);
    row.dataset.index = String(i);
    const fraction = fractionOutside(s, outside[i]);
    row.textContent = `#${i}  r ${number(s[3], 4)}  ${Number.isFinite(fraction) ? `${(100 * fraction).toFixed(1)}% outside` : ''}`;
    row.onclick = () => on.selectSphere(k, i);
    return row;
  });
  if (solid.spheres.length > maxSphereRows) {
    const more = document.createElement('div');
    more.className = 'more';
    more.textContent = `${solid.spheres.length - maxSphereRows} more: click them in the view`;
    rows.push(more);
  }
  return rows;
}
