// The server's HTTP API (docs/view.md). Every call carries the page's token; a failed call
// rejects with the server's own one-line error, never silently.
import { decodeGeometry } from './geometry.js';

export class ServerApi {
  constructor(token) {
    this.token = token;
  }

  async request(method, path, body, binary = false) {
    const headers = { 'X-Sphereset-Token': this.token };
    if (body !== undefined) headers['Content-Type'] = 'application/json';
    let response;
    try {
      response = await fetch(path, {
        method,
        headers,
        body: body === undefined ? undefined : JSON.stringify(body),
        cache: 'no-store',
      });
    } catch (e) {
      throw new Error(`${path}: the server does not answer (${e.message})`);
    }
    if (!response.ok) throw new Error(`${path}: ${await errorText(response)}`);
    return binary ? response.arrayBuffer() : response.json();
  }

  scene() { return this.request('GET', '/api/scene'); }
  // surface: 'displayed' (the original triangles of a repaired mesh) or 'repaired'.
  async geometry(solid, surface = 'displayed') {
    const query = surface === 'displayed' ? '' : `&surface=${surface}`;
    return decodeGeometry(await this.request('GET', `/api/geometry?solid=${solid}${query}`, undefined, true));
  }
  edit(solid, edits) { return this.request('POST', '/api/edit', { solid, edits }); }
  bound(solid) { return this.request('POST', '/api/bound', { solid }); }
  level(solid, level) { return this.request('POST', '/api/level', { solid, level }); }
  pose(joints) { return this.request('POST', '/api/pose', { joints }); }
  save(format) { return this.request('POST', '/api/save', format ? { format } : {}); }
  // { solid, spheres, quality } or { budget, quality }
  fit(request) { return this.request('POST', '/api/fit', request); }
  fitStatus() { return this.request('POST', '/api/fit/status', {}); }
  fitCancel() { return this.request('POST', '/api/fit/cancel', {}); }
}

async function errorText(response) {
  const status = `${response.status} ${response.statusText}`.trim();
  try {
    const body = await response.json();
    if (body && typeof body.error === 'string') return body.error;
  } catch {
    // Not JSON: the status line says enough.
  }
  return status;
}
