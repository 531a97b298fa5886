// The displayed mesh as the server sends it (docs/view.md), little-endian:
// uint32 V, uint32 T, float32 xyz x V, uint32 abc x T.

export function decodeGeometry(buffer) {
  if (buffer.byteLength < 8) throw new Error(`geometry: ${buffer.byteLength} bytes, not a mesh`);
  const view = new DataView(buffer);
  const vertexCount = view.getUint32(0, true);
  const triangleCount = view.getUint32(4, true);
  const expected = 8 + 12 * vertexCount + 12 * triangleCount;
  if (buffer.byteLength !== expected) {
    throw new Error(`geometry: ${buffer.byteLength} bytes for ${vertexCount} vertices and ` +
      `${triangleCount} triangles (expected ${expected})`);
  }
  // Read through the DataView: the format is little-endian whatever the machine is.
  const positions = new Float32Array(3 * vertexCount);
  let offset = 8;
  for (let i = 0; i < positions.length; i++, offset += 4) positions[i] = view.getFloat32(offset, true);
  const indices = new Uint32Array(3 * triangleCount);
  for (let i = 0; i < indices.length; i++, offset += 4) {
    const v = view.getUint32(offset, true);
    if (v >= vertexCount) throw new Error(`geometry: vertex index ${v} of ${vertexCount}`);
    indices[i] = v;
  }
  return { positions, indices };
}

export function base64ToArrayBuffer(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}
