// The box sorter, drawn with Konva from a BoxesState (src/plant/boxes.ts), seen from above: the
// belt with its boxes (large dark, small light, numbered), the photo-eyes lit while a box breaks
// them, the pusher and its plate across the belt, the side chute for large boxes and the bin at
// the end for small ones, the belt motor coloured by its speed, the run lamp, the counters, and
// the consequences on the drawing (a jammed box outlined red, JAM, a box fallen on the floor).
import { senseRecord } from '../../plant/points';
import { Circle, Group, Line, Rect, Text } from 'react-konva';
import {
  BELT_LENGTH_MM,
  BOX_LENGTH_MM,
  ENTRY_EYE_MM,
  PLATE_HALF_MM,
  PUSHER_EYE_MM,
  PUSHER_MM,
  SIZE_EYE_MM,
  boxes,
  frontOf,
  type Box,
  type BoxesState,
} from '../../plant/boxes';
import type { PlantDrawingProps } from './drawings';

export const BOXES_SIZE = { width: 300, height: 250 } as const;

const NO_FAULTS: ReadonlySet<string> = new Set();
const LIT = '#22c55e';
const DARK = '#4b5563';
const ALARM = '#dc2626';
const LARGE = '#92400e';
const SMALL = '#e2b66f';

/** The belt: x from the infeed, 0.084 px per mm; y across, its edge by the pusher at the top. */
const B = { x: 14, y: 78, w: 60 } as const;
const SCALE = 0.084;
const xOf = (mm: number) => B.x + mm * SCALE;
const BELT_END = xOf(BELT_LENGTH_MM);
const BOX_W = BOX_LENGTH_MM * SCALE;
/** Across the belt: a large box is wider than a small one (the same length along the belt). */
const acrossOf = (b: Box) => (b.large ? 44 : 28);

function Eye({ mm, on, label, high }: { mm: number; on: boolean; label: string; high?: boolean }) {
  const x = xOf(mm);
  // The size sensor's eye is high: drawn above the belt, the others below it.
  const dotY = high ? B.y - 12 : B.y + B.w + 10;
  return (
    <Group>
      <Line
        points={[x, B.y - 6, x, B.y + B.w + 6]}
        stroke={on ? ALARM : '#f87171'}
        strokeWidth={1}
        dash={high ? [2, 2] : [6, 3]}
        opacity={on ? 1 : 0.6}
      />
      <Circle x={x} y={dotY} radius={5} fill={on ? LIT : '#e5e7eb'} stroke="#111827" strokeWidth={1} />
      <Text
        text={label}
        x={x - 30}
        y={high ? dotY - 19 : dotY + 7}
        width={60}
        align="center"
        fontSize={10}
        fill="#374151"
      />
    </Group>
  );
}

function BoxShape({ b, front }: { b: Box; front: number }) {
  const across = acrossOf(b);
  // Its lane: along the edge by the pusher, pushed `side` of the belt's width towards the chute.
  const y = B.y + 4 + b.side * B.w;
  const x = xOf(front) - BOX_W;
  return (
    <Group x={x} y={y}>
      <Rect
        width={BOX_W}
        height={across}
        fill={b.large ? LARGE : SMALL}
        stroke={b.jammed ? ALARM : '#111827'}
        strokeWidth={b.jammed ? 3 : 1}
        cornerRadius={2}
      />
      <Text
        text={String(b.n)}
        width={BOX_W}
        y={across / 2 - 6}
        align="center"
        fontSize={11}
        fontStyle="bold"
        fill={b.large ? '#fef3c7' : '#1f2937'}
      />
    </Group>
  );
}

export function BoxesDrawing({ state, sensed }: PlantDrawingProps) {
  const s = state as BoxesState;
  const px = xOf(PUSHER_MM);
  const plateW = PLATE_HALF_MM * 2 * SCALE;
  // The plate's front across the belt (its face reaches the belt's edge at 1/11 of the stroke).
  const plateY = B.y + (s.pusher * 1.1 - 0.1) * B.w;
  // The eyes' lamps as the program reads them, faults applied (a stuck eye is lit with no box in
  // front of it: the boxes show where things really are).
  const eyes = sensed ?? senseRecord(boxes, s, NO_FAULTS);
  const jammed = s.boxes.some((b) => b.jammed);
  const motor = s.speed > 0.99 ? LIT : s.speed > 0.01 ? '#eab308' : DARK;
  const pusherColour = s.pusher > 0.98 ? LIT : s.pusher > 0.02 ? '#eab308' : DARK;
  // The belt's cleats move with it.
  const cleat = (s.belt * SCALE) % 20;
  return (
    <Group>
      {/* Counters. */}
      <Text text={`Sorted ${s.sorted}`} x={32} y={6} fontSize={13} fontStyle="bold" fill="#166534" />
      <Text
        text={`Missorted ${s.missorted}   Jams ${s.jams}   Fallen ${s.fallen}`}
        x={100}
        y={7}
        fontSize={11}
        fill={s.missorted + s.jams + s.fallen > 0 ? ALARM : '#374151'}
      />
      {/* Run lamp. */}
      <Circle
        x={16}
        y={14}
        radius={9}
        fill={s.lamp ? '#facc15' : '#e5e7eb'}
        stroke="#111827"
        strokeWidth={1}
      />
      <Text text="Run" x={-4} y={25} width={40} align="center" fontSize={10} fill="#374151" />
      {/* The belt, its cleats moving with it, the motor at the infeed. */}
      <Rect
        x={B.x}
        y={B.y}
        width={BELT_END - B.x}
        height={B.w}
        fill="#d1d5db"
        stroke="#111827"
        strokeWidth={1}
      />
      {Array.from({ length: Math.floor((BELT_END - B.x) / 20) }, (_, i) => {
        const x = B.x + i * 20 + cleat;
        return x < BELT_END ? (
          <Line key={i} points={[x, B.y + 1, x, B.y + B.w - 1]} stroke="#9ca3af" strokeWidth={1} />
        ) : null;
      })}
      <Group x={B.x + 6} y={B.y + B.w + 42}>
        <Circle radius={12} fill={motor} stroke="#111827" strokeWidth={1} />
        <Text
          text="M"
          x={-6}
          y={-6}
          width={12}
          align="center"
          fontSize={12}
          fontStyle="bold"
          fill="#f9fafb"
        />
        <Text text="Belt" x={14} y={-5} fontSize={10} fill="#374151" />
      </Group>
      <Text text="Infeed" x={B.x - 10} y={B.y - 14} fontSize={10} fill="#374151" />
      {/* The chute for large boxes, beside the belt at the pusher. */}
      <Line
        points={[
          px - plateW / 2 - 4,
          B.y + B.w,
          px - plateW / 2 - 10,
          194,
          px + plateW / 2 + 10,
          194,
          px + plateW / 2 + 4,
          B.y + B.w,
        ]}
        closed
        fill="#f3f4f6"
        stroke="#111827"
        strokeWidth={1}
      />
      <Text
        text={`Chute (large)\n${s.largeChute}`}
        x={px - 45}
        y={197}
        width={90}
        align="center"
        fontSize={10}
        fill="#374151"
      />
      {/* The bin for small boxes at the belt's end. */}
      <Rect
        x={BELT_END + 4}
        y={B.y - 8}
        width={44}
        height={B.w + 16}
        fill="#f3f4f6"
        stroke="#111827"
        strokeWidth={1}
      />
      <Text
        text={`Bin\n(small)\n${s.smallBin}`}
        x={BELT_END + 4}
        y={B.y + 12}
        width={44}
        align="center"
        fontSize={10}
        fill="#374151"
      />
      {/* Photo-eyes. */}
      <Eye mm={ENTRY_EYE_MM} on={eyes.EntryEye === true} label="Entry" />
      <Eye mm={SIZE_EYE_MM} on={eyes.SizeEye === true} label="Size (high)" high />
      <Eye mm={PUSHER_EYE_MM} on={eyes.PusherEye === true} label="At pusher" />
      {/* Boxes. */}
      {s.boxes.map((b) => (
        <BoxShape key={b.n} b={b} front={frontOf(s, b)} />
      ))}
      {/* The pusher: cylinder above the belt, rod and plate across it. */}
      <Rect x={px - 8} y={30} width={16} height={26} fill={pusherColour} stroke="#111827" strokeWidth={1} />
      <Line points={[px, 56, px, plateY]} stroke="#111827" strokeWidth={3} />
      <Rect x={px - plateW / 2} y={plateY - 4} width={plateW} height={5} fill="#374151" />
      <Text text="Pusher" x={px - 48} y={34} fontSize={10} fill="#374151" />
      <Circle
        x={px + 16}
        y={40}
        radius={4}
        fill={eyes.PusherIn === true ? LIT : '#e5e7eb'}
        stroke="#111827"
        strokeWidth={1}
      />
      <Text text="In" x={px + 22} y={35} fontSize={9} fill="#374151" />
      <Circle
        x={px + 40}
        y={40}
        radius={4}
        fill={eyes.PusherOut === true ? LIT : '#e5e7eb'}
        stroke="#111827"
        strokeWidth={1}
      />
      <Text text="Out" x={px + 46} y={35} fontSize={9} fill="#374151" />
      {/* Consequences. */}
      {jammed && <Text text="JAM" x={px - 40} y={54} fontSize={14} fontStyle="bold" fill={ALARM} />}
      {s.fallen > 0 && (
        <Group x={px + plateW / 2 + 20} y={196} rotation={-20}>
          <Rect width={BOX_W} height={22} fill={SMALL} stroke={ALARM} strokeWidth={2} />
          <Text text="FELL" width={BOX_W} y={6} align="center" fontSize={9} fontStyle="bold" fill={ALARM} />
        </Group>
      )}
    </Group>
  );
}
