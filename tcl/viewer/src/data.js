// SPDX-License-Identifier: MIT
// Reads the data block written by the Viewer recorder (tcl/domain/ViewerRecorder.cpp).
//
// Every time series (node displacement component, contact status, gap and normal force, bearing
// damage and shear strain, ground acceleration, plotted quantity) is stored as [q, offset]: its values are q * k_i, where the integers k_i were
// written as zigzag LEB128 varints of the differences k_i - k_{i-1} (k_{-1} = 0), starting at
// byte `offset` of the base64 string `bytes`. One series holds `frames` values.

/** Decodes the base64 string into bytes (atob is available in every browser and in node). */
export function decodeBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/** Values of one series [q, offset] of `count` values as a Float64Array. */
export function decodeSeries(bytes, series, count) {
  const [q, offset] = series;
  const out = new Float64Array(count);
  let pos = offset;
  let k = 0;
  for (let i = 0; i < count; ++i) {
    let zz = 0;
    let scale = 1;
    let b;
    do {
      b = bytes[pos++];
      zz += (b & 0x7f) * scale;  // multiplication, not <<, so deltas beyond 2^31 stay exact
      scale *= 128;
    } while (b & 0x80);
    const delta = zz % 2 === 0 ? zz / 2 : -(zz + 1) / 2;
    k += delta;
    out[i] = k * q;
  }
  return out;
}

/** Parses the JSON data block and decodes every series. */
export function readData(text) {
  const d = JSON.parse(text);
  if (d.format !== 'dabs-viewer') throw new Error('not a dabs-viewer data block');
  const n = d.frames;
  const bytes = decodeBase64(d.bytes);
  const s = (series) => decodeSeries(bytes, series, n);
  const nodeIndex = new Map(d.nodes.map((tag, i) => [tag, i]));
  const disp = d.nodes.map((_, i) => [s(d.disp[3 * i]), s(d.disp[3 * i + 1]), s(d.disp[3 * i + 2])]);
  return {
    title: d.title,
    ndm: d.ndm,
    frames: n,
    time: Float64Array.from(d.time),
    nodes: d.nodes,
    nodeIndex,
    coords: d.coords,
    // shape: a beam's section outline [y0, z0, y1, z1, ..] in local axes, or a bearing's pad
    // [lx, ly]; empty when none was given
    elements: d.elements.map(([tag, kind, type, nodes, shape]) => ({ tag, kind, type, nodes, shape: shape || [] })),
    disp,
    blocks: (d.blocks || []).map(([node, lx, ly, lz, dz]) => ({ node, size: [lx, ly, lz], dz: dz || 0 })),
    gaps: (d.gaps || []).map(([label, a, b]) => ({ label, a, b })),
    contacts: d.contacts.map(([tag, status, gap, force]) => ({
      tag, status: s(status), gap: gap ? s(gap) : null, force: force ? s(force) : null })),
    bearings: d.bearings.map(([tag, damage, strain]) => ({ tag, damage: s(damage), strain: strain ? s(strain) : null })),
    ground: (d.ground || []).map(([dof, series]) => ({ dof, accel: s(series) })),
    plots: d.plots.map((p) => ({ label: p.label, source: p.source, values: s(p.values) })),
  };
}
