// The colour ramp of the spheres: each sphere by its own outside volume, from 0 (blue-green)
// to the largest in the scene (red).
import { Color } from 'three';

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

// The same ramp as a CSS gradient, for the legend.
export function rampGradient() {
  const parts = stops.map(([t, c]) => `#${c.toString(16).padStart(6, '0')} ${t * 100}%`);
  return `linear-gradient(to right, ${parts.join(', ')})`;
}
