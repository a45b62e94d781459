// Keeps the simulator's machine in step with the project's (`project.plant`, issue 26): opening a
// project or example that names a machine attaches it; choosing another in the Plant panel, or
// changing an address, re-attaches it. A machine newly attached (an exercise opened from File >
// Examples, a project naming one) shows the Plant tab: the machine is what the project is about.
// Mounted once (panels.ts HOSTS).
import { useEffect, useRef } from 'react';
import type { DocumentState } from '../../store/documentStore';
import { useDocument } from '../../store/documentStore';
import { useSimStore } from '../sim/simContext';

const selectPlant = (s: DocumentState) => s.project.plant;

export function PlantHost() {
  const plant = useDocument(selectPlant);
  const sim = useSimStore();
  const sent = useRef<string>('null');
  const shown = useRef<string | undefined>(undefined);
  useEffect(() => {
    const key = JSON.stringify(plant ?? null);
    if (key === sent.current) return;
    sent.current = key;
    sim.getState().setPlant(plant ? { id: plant.id, ...(plant.map ? { map: plant.map } : {}) } : null);
  }, [plant, sim]);
  const id = plant?.id;
  useEffect(() => {
    if (id === shown.current) return;
    shown.current = id;
    if (id) document.getElementById('rs-tab-plant')?.click();
  }, [id]);
  return null;
}
