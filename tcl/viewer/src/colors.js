// SPDX-License-Identifier: MIT
// Colour scale of the bearings' shear strain: blue when small, yellow at the design limit (250 %),
// red at failure (300 %) and beyond. Shared by the page and its browser test.

/** Shear strain of the design limit and of failure (yoshidaBearing -limits defaults). */
export const kDesignStrain = 2.5;
export const kFailureStrain = 3.0;
/** Strain at the right end of the drawn scale. */
export const kStrainScale = 3.5;

// [strain, r, g, b]: linear between the stops, constant beyond the last.
const kStops = [
  [0.0, 0x2b, 0x57, 0xc4],
  [1.0, 0x4f, 0xa8, 0xd8],
  [2.0, 0x9c, 0xd0, 0x6a],
  [kDesignStrain, 0xf2, 0xc8, 0x1e],
  [kFailureStrain, 0xd6, 0x27, 0x28],
  [kStrainScale, 0x8b, 0x00, 0x00],
];

/** '#rrggbb' of a shear strain (absolute value; 1.0 = 100 %). */
export function strainColor(strain) {
  const s = Math.abs(Number(strain)) || 0;
  let k = 0;
  while (k + 1 < kStops.length && s > kStops[k + 1][0]) ++k;
  const a = kStops[k];
  const b = kStops[Math.min(k + 1, kStops.length - 1)];
  const w = b[0] > a[0] ? Math.min(Math.max((s - a[0]) / (b[0] - a[0]), 0), 1) : 0;
  const c = [1, 2, 3].map((i) => Math.round(a[i] + w * (b[i] - a[i])));
  return '#' + c.map((v) => v.toString(16).padStart(2, '0')).join('');
}
