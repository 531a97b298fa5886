// The colour ramp of the spheres, from 0 (blue) to 1 (red): by default each sphere's fraction of
// its own volume outside the solid (an absolute scale: the same colour means the same waste
// whatever the other spheres do), or, as an option, its outside volume over the largest in the
// scene. The gaps (uncovered triangles) have a colour of their own, on no ramp.
import { Color } from 'three';

export const gapColor = 0xff00ff;  // magenta: neither blue, green, yellow nor red

const stops = [
  [0.0, 0x2c7bb6],
  [0.25, 0x00a6ca],
  [0.5, 0x90eb9d],
  [0.75, 0xf9d057],
  [1.0, 0xd7191c],
];

export function rampColor(t, target = new Color()) {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0));
  for (let i = 1; i < stops.length; i++) {
    if (x <= stops[i][0]) {
      const [t0, c0] = stops[i - 1];
      const [t1, c1] = stops[i];
      return target.setHex(c0).lerp(new Color(c1), (x - t0) / (t1 - t0));
    }
  }
  return target.setHex(stops[stops.length - 1][1]);
}

// The ramp's stops as [t, '#rrggbb'], for a canvas gradient.
export function rampStops() {
  return stops.map(([t, c]) => [t, `#${c.toString(16).padStart(6, '0')}`]);
}

// The same ramp as a CSS gradient, for the legend.
export function rampGradient() {
  const parts = stops.map(([t, c]) => `#${c.toString(16).padStart(6, '0')} ${t * 100}%`);
  return `linear-gradient(to right, ${parts.join(', ')})`;
}

// The fraction of sphere [x,y,z,r] outside the solid, from its `outside` volume (NaN unknown).
export function fractionOutside(sphere, outside) {
  const r = sphere[3];
  const volume = (4 / 3) * Math.PI * r * r * r;
  return volume > 0 && Number.isFinite(outside) ? Math.min(1, outside / volume) : NaN;
}

// Where sphere [x,y,z,r] with `outside` volume outside the solid sits on the ramp: 'absolute',
// its fraction outside (0 to 1); 'relative', outside over `largest`.
export function sphereShade(sphere, outside, scale, largest) {
  const v = Number.isFinite(outside) ? outside : 0;
  if (scale === 'relative') return largest > 0 ? v / largest : 0;
  const f = fractionOutside(sphere, v);
  return Number.isFinite(f) ? f : 0;
}
