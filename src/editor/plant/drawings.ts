// How each machine is drawn (issue 26): one Konva component per machine id, given the machine's
// state (a frame's, or a recorded scan's). The model itself (src/plant) knows nothing of drawing.
import type { ComponentType } from 'react';
import type { Value } from '../../model/iecTypes';
import { BoxesDrawing, BOXES_SIZE } from './BoxesDrawing';
import { GarageDrawing, GARAGE_SIZE } from './GarageDrawing';
import { IntersectionDrawing, INTERSECTION_SIZE } from './IntersectionDrawing';
import { LiftDrawing, LIFT_SIZE } from './LiftDrawing';
import { MixerDrawing, MIXER_SIZE } from './MixerDrawing';
import { TankDrawing, TANK_SIZE } from './TankDrawing';

export interface PlantDrawingProps {
  readonly state: unknown;
  /**
   * The sensors as the program reads them in that state, faults applied (a switch stuck OFF
   * reads OFF under water): what a sensor's lamp on the drawing shows, by point name.
   */
  readonly sensed?: Readonly<Record<string, Value>>;
}

export interface PlantDrawing {
  readonly component: ComponentType<PlantDrawingProps>;
  readonly width: number;
  readonly height: number;
}

export const PLANT_DRAWINGS: Readonly<Record<string, PlantDrawing>> = {
  tank: { component: TankDrawing, ...TANK_SIZE },
  boxes: { component: BoxesDrawing, ...BOXES_SIZE },
  garage: { component: GarageDrawing, ...GARAGE_SIZE },
  lift: { component: LiftDrawing, ...LIFT_SIZE },
  mixer: { component: MixerDrawing, ...MIXER_SIZE },
  intersection: { component: IntersectionDrawing, ...INTERSECTION_SIZE },
};
