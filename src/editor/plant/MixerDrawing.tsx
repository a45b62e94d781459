// The batch mixer, drawn with Konva from a MixerState (src/plant/mixer.ts): the vessel with its
// batch (coloured by the share of A and B), the ingredient and outlet valves coloured by how far
// they open, the agitator turning with its motor coloured by speed, the heater glowing while it
// heats, the level switches lit when ON, the temperature, the batch counts, the done lamp, and
// overflow / scorch / dry heater / spoiled batch shown on the drawing.
import { Circle, Group, Line, Rect, Text } from 'react-konva';
import {
  HIGH_SWITCH_L,
  LOW_SWITCH_L,
  MID_SWITCH_L,
  MIXER_CAPACITY_L,
  OVERHEAT_C,
  ratioOf,
  type MixerState,
  type SpoilReason,
} from '../../plant/mixer';
import type { PlantDrawingProps } from './drawings';

export const MIXER_SIZE = { width: 340, height: 290 } as const;

/** A is yellow, B blue: a batch half and half is green. */
const A_COLOUR = [250, 204, 21] as const;
const B_COLOUR = [14, 165, 233] as const;
const PIPE = '#9ca3af';
const LIT = '#22c55e';
const MOVING = '#eab308';
const DARK = '#4b5563';
const ALARM = '#dc2626';
const INK = '#111827';
const LABEL = '#374151';

/** The vessel: x 120..240, y 50..230 (180 px for 1,000 L). */
const V = { x: 120, y: 50, w: 120, h: 180 } as const;
const yOf = (litres: number) => V.y + V.h - (litres / MIXER_CAPACITY_L) * V.h;
const rgb = (c: readonly number[]) => `rgb(${c.map((x) => Math.round(x)).join(',')})`;
/** The batch's colour: A's and B's mixed by their shares. */
const mixColour = (shareA: number) => rgb(A_COLOUR.map((a, i) => a * shareA + B_COLOUR[i]! * (1 - shareA)));
const SPOIL_WORD: Record<SpoilReason, string> = {
  '': '',
  overheat: 'overheated',
  scorch: 'scorched',
  ratio: 'ratio',
  unheld: 'not held',
  short: 'short',
};
const runColour = (x: number) => (x > 0.99 ? LIT : x > 0.01 ? MOVING : DARK);

function Valve({ x, y, open, label }: { x: number; y: number; open: number; label: string }) {
  return (
    <Group x={x} y={y}>
      <Line
        points={[-10, -8, 10, 8, 10, -8, -10, 8]}
        closed
        fill={runColour(open)}
        stroke={INK}
        strokeWidth={1}
      />
      <Text text={label} x={-30} y={11} width={60} align="center" fontSize={10} fill={LABEL} />
    </Group>
  );
}

function LevelSwitch({ litres, on, label }: { litres: number; on: boolean; label: string }) {
  const y = yOf(litres);
  return (
    <Group>
      <Line points={[V.x + V.w, y, V.x + V.w + 14, y]} stroke={DARK} strokeWidth={2} />
      <Circle x={V.x + V.w + 20} y={y} radius={6} fill={on ? LIT : '#e5e7eb'} stroke={INK} strokeWidth={1} />
      <Text text={label} x={V.x + V.w + 30} y={y - 6} fontSize={11} fill={INK} />
    </Group>
  );
}

/** A consequence, in the column left of the vessel (below the done lamp). */
function Alarm({ text, row }: { text: string; row: number }) {
  return (
    <Text text={text} x={4} y={140 + row * 16} width={112} fontSize={12} fontStyle="bold" fill={ALARM} />
  );
}

export function MixerDrawing({ state, sensed }: PlantDrawingProps) {
  const s = state as MixerState;
  const top = yOf(s.level);
  const shareA = s.level > 0 ? ratioOf(s) / 100 : 0.5;
  const liquid = mixColour(shareA);
  const cx = V.x + V.w / 2;
  const bladeY = V.y + V.h - 38;
  // The blades seen from the side: their width follows the angle they have turned to.
  const blade = 30 * Math.abs(Math.cos((s.angle * Math.PI) / 180));
  const heaterY = V.y + V.h - 12;
  const heaterColour = s.heating ? (s.level >= 60 ? '#f97316' : ALARM) : DARK;
  const inA = s.valveA > 0.01;
  const inB = s.valveB > 0.01;
  return (
    <Group>
      {/* Counts. */}
      <Text
        text={`Batches ${s.batches}   Spoiled ${s.spoiled}`}
        x={6}
        y={6}
        fontSize={12}
        fontStyle="bold"
        fill={s.spoiled > 0 ? ALARM : INK}
      />
      {/* Ingredient A from the left, B from the right, over the rim. */}
      <Line points={[6, 34, 150, 34, 150, V.y + 4]} stroke={inA ? rgb(A_COLOUR) : PIPE} strokeWidth={6} />
      <Valve x={95} y={34} open={s.valveA} label="A" />
      <Line points={[334, 34, 210, 34, 210, V.y + 4]} stroke={inB ? rgb(B_COLOUR) : PIPE} strokeWidth={6} />
      <Valve x={270} y={34} open={s.valveB} label="B" />
      {/* Vessel and batch. */}
      <Rect x={V.x} y={V.y} width={V.w} height={V.h} stroke={INK} strokeWidth={2} fill="#f3f4f6" />
      <Rect x={V.x + 1} y={top} width={V.w - 2} height={V.y + V.h - top - 1} fill={liquid} opacity={0.8} />
      {inA && (
        <Rect
          x={147}
          y={V.y + 4}
          width={6}
          height={Math.max(0, top - V.y - 4)}
          fill={rgb(A_COLOUR)}
          opacity={0.6}
        />
      )}
      {inB && (
        <Rect
          x={207}
          y={V.y + 4}
          width={6}
          height={Math.max(0, top - V.y - 4)}
          fill={rgb(B_COLOUR)}
          opacity={0.6}
        />
      )}
      {/* Agitator: motor on the lid, shaft, blades. */}
      <Rect
        x={cx - 14}
        y={V.y - 20}
        width={28}
        height={18}
        fill={runColour(s.agitator)}
        stroke={INK}
        strokeWidth={1}
      />
      <Text
        text="M"
        x={cx - 14}
        y={V.y - 17}
        width={28}
        align="center"
        fontSize={12}
        fontStyle="bold"
        fill="#f9fafb"
      />
      <Line points={[cx, V.y - 2, cx, bladeY]} stroke={INK} strokeWidth={3} />
      <Line points={[cx - blade, bladeY, cx + blade, bladeY]} stroke={INK} strokeWidth={6} lineCap="round" />
      {/* Heater element at the bottom. */}
      <Line
        points={[
          V.x + 18,
          heaterY,
          V.x + 30,
          heaterY - 6,
          V.x + 42,
          heaterY,
          V.x + 54,
          heaterY - 6,
          V.x + 66,
          heaterY,
          V.x + 78,
          heaterY - 6,
          V.x + 90,
          heaterY,
          V.x + 102,
          heaterY - 6,
        ]}
        stroke={heaterColour}
        strokeWidth={4}
      />
      <Text text="Heater" x={V.x + 4} y={V.y + V.h + 4} fontSize={10} fill={LABEL} />
      {/* What the vessel holds, on a plate in front of the shaft. */}
      <Rect
        x={V.x + 22}
        y={V.y + 42}
        width={V.w - 44}
        height={s.level > 0 ? 60 : 44}
        fill="#ffffff"
        opacity={0.85}
        cornerRadius={4}
      />
      <Text
        text={`${Math.round(s.level)} L\n${s.temp.toFixed(1)} °C`}
        x={V.x}
        y={V.y + 48}
        width={V.w}
        align="center"
        fontSize={14}
        fontStyle="bold"
        lineHeight={1.2}
        fill={s.temp > OVERHEAT_C ? ALARM : INK}
      />
      {s.level > 0 && (
        <Text
          text={`A ${Math.round(shareA * 100)} % B ${Math.round((1 - shareA) * 100)} %`}
          x={V.x}
          y={V.y + 88}
          width={V.w}
          align="center"
          fontSize={11}
          fill={INK}
        />
      )}
      <LevelSwitch
        litres={HIGH_SWITCH_L}
        on={sensed ? sensed.HighLevel === true : s.level >= HIGH_SWITCH_L}
        label="High"
      />
      <LevelSwitch
        litres={MID_SWITCH_L}
        on={sensed ? sensed.MidLevel === true : s.level >= MID_SWITCH_L}
        label="Mid"
      />
      <LevelSwitch
        litres={LOW_SWITCH_L}
        on={sensed ? sensed.LowLevel === true : s.level >= LOW_SWITCH_L}
        label="Low"
      />
      {/* Outlet to the filling line. */}
      <Line
        points={[cx, V.y + V.h, cx, 252, 334, 252]}
        stroke={s.outflow > 0 ? liquid : PIPE}
        strokeWidth={6}
      />
      <Valve x={290} y={252} open={s.outlet} label="Outlet" />
      {/* Done lamp. */}
      <Circle x={40} y={110} radius={11} fill={s.lamp ? LIT : '#e5e7eb'} stroke={INK} strokeWidth={1} />
      <Text text="Done" x={20} y={124} width={40} align="center" fontSize={10} fill={LABEL} />
      {/* Consequences on the drawing. */}
      {s.overflowing && (
        <Group>
          <Line points={[V.x, V.y, V.x - 12, V.y + 40]} stroke={liquid} strokeWidth={4} />
          <Line points={[V.x + V.w, V.y, V.x + V.w + 12, V.y + 40]} stroke={liquid} strokeWidth={4} />
          <Alarm text="OVERFLOW" row={0} />
        </Group>
      )}
      {s.scorching && <Alarm text="SCORCHED" row={1} />}
      {s.burntOut ? <Alarm text="HEATER BURNT OUT" row={2} /> : s.dryHeating && <Alarm text="HEATER DRY" row={2} />}
      {s.spoiledBatch && <Alarm text={`SPOILED (${SPOIL_WORD[s.spoilReason]})`} row={3} />}
    </Group>
  );
}
