// The built-in simulated I/O device: 16 DI, 16 DO, 4 AI, 4 AO on the OpenPLC default map, also
// served as a Modbus TCP server on loopback so mbpoll or a plant simulator can drive its inputs.
import type { AddressInfo, Server, Socket } from 'node:net';
import type { DeviceOutputs } from '../protocol/messages';
import type { Quality, WireValue } from '../protocol/points';
import { safeImage, type Device, type DeviceListener, type Values } from './device';
import { freeLoopbackPort, ModbusServer } from './modbusLib';
import { expandPoints, type DevicePoint } from './pointMap';
import { requirePlant } from '../plant/machines';
import { addressKey, PlantLoop } from '../plant/loop';
import type { Value } from '../model/iecTypes';
import type { PlantModel } from '../plant/types';

/** A machine's step in real time (virtual commissioning): every this many ms of wall time. */
const PLANT_STEP_MS = 20;
/**
 * `--plant`: the device's communication watchdog, as an I/O coupler's (Beckhoff BK9000: on, 1000 ms,
 * re-triggered by write telegrams, outputs to 0): no write to the machine's actuators for this long
 * and the outputs the Modbus master wrote fall OFF / 0. A PLC rewrites its outputs every cycle.
 */
export const PLANT_MASTER_WATCHDOG_MS = 1000;

export const SIMULATED_DEVICE_ID = 'sim';
/** Writable windows for driving the simulated inputs over Modbus (OpenPLC leaves these free). */
export const SIM_INPUT_COIL_BASE = 800; // coil 800+n sets discrete input n (%IX bit n)
export const SIM_INPUT_REGISTER_BASE = 2048; // holding register 2048+n sets input register n (%IWn)

const SIM_POINTS: readonly DevicePoint[] = expandPoints(
  [
    { address: '%IX0.0', count: 16, hold: false },
    { address: '%QX0.0', count: 16, hold: false },
    { address: '%IW0', count: 4, hold: false },
    { address: '%QW0', count: 4, hold: false },
  ],
  'simulated device',
);

const ILLEGAL_ADDRESS = { modbusErrorCode: 0x02, msg: 'Illegal data address' };
const ILLEGAL_FUNCTION = { modbusErrorCode: 0x01, msg: 'Outputs belong to the controller' };
/** `--plant`: the machine's sensors drive their inputs, as wires do; a Modbus write to one is refused. */
const MACHINE_SENSOR = { modbusErrorCode: 0x01, msg: "Sensors belong to the machine" };
/** `--plant`: a Modbus write to an actuator the gateway's controller drives is refused (two masters). */
const CONTROLLER_DRIVES = { modbusErrorCode: 0x06, msg: "The gateway's controller drives the machine's actuators" };
/**
 * `--plant`: after a Modbus master last wrote the machine's actuators, `arm` waits this long (it is
 * probably a PLC still writing them every cycle), as for another master on a real device.
 */
export const PLANT_MASTER_QUIET_MS = 3000;

/**
 * `--plant`: the first of a machine's points the simulated device has no place for (its default
 * address is not among the device's 16 DI, 16 DO, 4 AI, 4 AO), as a sentence; undefined when all fit.
 */
export function simulatedDeviceMisfit(model: Pick<PlantModel, 'id' | 'points'>): string | undefined {
  const on = new Set(SIM_POINTS.map((p) => addressKey(p.address)));
  const out = model.points.find((p) => !on.has(addressKey(p.address)));
  return (
    out &&
    `the machine "${model.id}"'s ${out.kind} ${out.name} at ${out.address} has no place on the simulated device (%IX0.0-%IX1.7, %QX0.0-%QX1.7, %IW0-%IW3, %QW0-%QW3)`
  );
}

export class SimulatedDevice implements Device {
  readonly info = { id: SIMULATED_DEVICE_ID, kind: 'simulated' as const, target: 'simulated' };
  readonly points = SIM_POINTS;
  readonly state = 'online' as const;
  readonly error = null;
  private readonly values = new Map<string, WireValue>(SIM_POINTS.map((p) => [p.address, p.type === 'BOOL' ? false : 0]));
  private readonly byTable = new Map<string, DevicePoint>(SIM_POINTS.map((p) => [`${p.table}:${p.register}`, p]));
  private listener: DeviceListener | undefined;
  private mode: 'drive' | 'safe' = 'safe';
  private final = false;
  private server: ModbusServer | undefined;
  private port: number | undefined;
  /** `--plant`: the machine whose I/O this device is, and its real-time stepping. */
  private readonly plant: PlantLoop | undefined;
  private plantTimer: ReturnType<typeof setInterval> | undefined;
  /**
   * `--plant`: the outputs a Modbus master (the PLC under test) wrote. When the last master's
   * connection closes they fall OFF / 0, as a PLC's outputs do when it stops or is unplugged (its
   * contactors drop out; a coupler's communication watchdog does the same): a pump is not left
   * running into an overflow by a PLC that is gone.
   */
  private readonly masterWritten = new Set<string>();
  /**
   * `--plant`: the communication watchdog (PLANT_MASTER_WATCHDOG_MS), fed by every Modbus write to the
   * machine's actuators. A master that stays connected but stops writing (hung, its cable pulled
   * without TCP noticing, another client such as an HMI keeping a connection open) loses its outputs.
   */
  private masterWatchdog: ReturnType<typeof setTimeout> | undefined;
  /** `--plant`: the machine's push buttons (momentary) held pressed over Modbus (coil 800 + n), by address. */
  private readonly buttonsHeld = new Set<string>();
  /**
   * `--plant`: two masters. The peer (`127.0.0.1:40312`) whose Modbus request is being served: set
   * by a timer queued before modbus-serial's own for each request it parses (see startModbusServer).
   */
  private peer: string | undefined;
  /** Counts the requests (the socket reads) served, to refuse a multiple write whole (below). */
  private requestSeq = 0;
  /** The request whose actuator write was refused: its other coils/registers are refused too. */
  private refusedSeq = -1;
  /** `--plant`: the last Modbus write to the machine's actuators, by whom, of what. */
  private lastMasterWrite: { peer: string; address: string; value: WireValue; at: number } | undefined;
  /** `--plant`: a Modbus master wrote an actuator while the gateway's controller drove them; cleared by the next drive. */
  private conflictText: string | null = null;

  /**
   * @param modbusPort loopback port of the Modbus server (0: any free port; null: no server).
   * @param plant a machine (`tank`): its sensors drive the inputs, its actuators are the coils a Modbus master writes.
   * @param log the gateway's log: the machine's consequences (the tank overflowed) and its outputs falling when the PLC goes.
   * @param masterWatchdogMs `--plant`: no write to the actuators for this long and the master's outputs fall OFF (0: never).
   */
  constructor(
    private readonly modbusPort: number | null,
    plant?: string,
    private readonly log: (line: string) => void = () => undefined,
    private readonly masterWatchdogMs: number = PLANT_MASTER_WATCHDOG_MS,
  ) {
    const model = plant === undefined ? undefined : requirePlant(plant);
    const misfit = model && simulatedDeviceMisfit(model);
    if (misfit) throw new Error(misfit);
    this.plant = model && new PlantLoop(model, {}, 0);
  }

  /**
   * `--plant`: why setting `address` by hand (the Hardware panel, a Modbus write) is refused, when it
   * is one of the machine's sensors: the machine writes it only when it changes, so a value set over
   * it would stay (a limit switch ON with nothing behind it). Undefined for any other input.
   */
  machineSensorRefusal(address: string): string | undefined {
    const sensor = this.plant?.points.find((q) => q.kind === 'sensor' && addressKey(q.address) === addressKey(address));
    return sensor && `${address} is the machine "${this.plant!.model.id}"'s sensor ${sensor.name}: the machine sets it`;
  }

  /** `--plant`: the machine's quantity (`level`), for tests and logs. */
  plantRead(name: string): Value | undefined {
    return this.plant?.read(name);
  }

  /** The loopback port the Modbus server listens on, once started. */
  get modbusServerPort(): number | undefined {
    return this.port;
  }

  inputValues(): Values {
    return new Map([...this.values].filter(([a]) => a.startsWith('%I')));
  }
  inputQuality(): ReadonlyMap<string, Quality> {
    return new Map(SIM_POINTS.filter((p) => p.dir === 'in').map((p) => [p.address, 'good' as const]));
  }
  writtenValues(): Values {
    return new Map([...this.values].filter(([a]) => a.startsWith('%Q')));
  }
  queueDepth(): number {
    return 0;
  }

  async start(listener: DeviceListener): Promise<void> {
    this.listener = listener;
    if (this.plant) this.startPlant(this.plant);
    if (this.modbusPort === null) return;
    await this.startModbusServer(this.modbusPort === 0 ? await freeLoopbackPort() : this.modbusPort);
  }

  /** Sets simulated inputs (already validated by the caller); notifies changed ones. */
  setInputs(values: Values): void {
    const changed = new Map<string, WireValue>();
    for (const [address, value] of values) {
      if (this.values.get(address) !== value) changed.set(address, value);
      this.values.set(address, value);
    }
    if (changed.size) this.listener?.inputs(changed, new Map([...changed.keys()].map((a) => [a, 'good' as const])));
  }

  /**
   * Inputs set from outside: the Hardware panel, a Modbus write into the input windows. With a
   * machine, one of its operator controls is operated on the machine too (the garage's Doorway
   * drives a car in: its photo-eye then sees it), not only shown to the program.
   */
  simulateInputs(values: Values): void {
    const plant = this.plant;
    if (plant)
      for (const [address, value] of values) {
        const op = plant.points.find((q) => q.kind === 'operator' && addressKey(q.address) === addressKey(address));
        if (op) plant.setOperator(op.name, value === true);
      }
    this.setInputs(values);
  }

  outputsState(): DeviceOutputs {
    return this.mode === 'drive' ? 'driven' : 'safe';
  }

  /** `--plant`: what the other master did, while the gateway's controller is kept off the actuators for it. */
  conflict(): string | null {
    return this.mode === 'drive' ? null : this.conflictText;
  }

  /**
   * `--plant`: a Modbus master (a PLC under test, a script) wrote the machine's actuators moments ago:
   * it is driving the machine, and the controller arming would fight it. Null when arming is allowed.
   */
  armBlocker(): string | null {
    const w = this.lastMasterWrite;
    if (!this.plant || !w) return null;
    const ago = Date.now() - w.at;
    if (ago >= PLANT_MASTER_QUIET_MS) return null;
    return `another Modbus master (${w.peer}) is writing the machine "${this.plant.model.id}"'s actuators (${this.pointWords(w.address)} ${(ago / 1000).toFixed(1)} s ago): stop it, then arm`;
  }

  drive(values: Values): void {
    if (this.final) return;
    if (this.mode !== 'drive') {
      this.mode = 'drive';
      this.conflictText = null;
      // The controller drives the machine now: what a Modbus master wrote before is not its to drop
      // (its watchdog or its disconnect must not switch the controller's outputs off).
      this.masterWritten.clear();
      clearTimeout(this.masterWatchdog);
      this.masterWatchdog = undefined;
      this.listener?.status();
    }
    this.writeOutputs(values);
  }

  /** `Pump (%QX0.0)`: the machine's name of a point, with its address. */
  private pointWords(address: string): string {
    const name = this.plant?.points.find((p) => addressKey(p.address) === addressKey(address))?.name;
    return name ? `${name} (${address})` : address;
  }

  /**
   * `--plant`: a Modbus master writes one of the machine's actuators. While the gateway's controller
   * (the page) drives them, that is two masters on one machine: the write is refused (exception 06,
   * busy), and the hub is told, as for another master on a real device: it disarms, the safe image
   * is written, and the page says which point and which master. Otherwise it is the master's output.
   */
  private actuatorWrite(address: string, value: WireValue): void {
    const peer = this.peer ?? 'a Modbus client';
    const drove = this.values.get(address);
    this.lastMasterWrite = { peer, address, value, at: Date.now() };
    // modbus-serial serves a multiple write (FC15/FC16) one coil at a time: once its first one was
    // refused (and the gateway disarmed), the rest of it must not land half-written.
    if (this.refusedSeq === this.requestSeq) throw CONTROLLER_DRIVES;
    if (this.mode !== 'drive') {
      this.masterWrote(address, value);
      return;
    }
    const show = (v: WireValue | undefined) => (typeof v === 'boolean' ? (v ? 'ON' : 'OFF') : String(v));
    this.conflictText = `another Modbus master (${peer}) wrote the machine "${this.plant!.model.id}"'s ${this.pointWords(address)} ${show(value)} while this gateway's controller drives it (${show(drove)}); the write was refused`;
    this.refusedSeq = this.requestSeq;
    this.log(`machine "${this.plant!.model.id}": ${this.conflictText}`);
    this.listener?.otherMaster?.(this.conflictText);
    throw CONTROLLER_DRIVES;
  }

  /** In-process: the safe image is on the device as soon as it is asked for. */
  safe(): Promise<boolean> {
    if (this.mode !== 'safe') {
      this.mode = 'safe';
      this.writeOutputs(safeImage(this.points, this.writtenValues(), (p) => (p.type === 'BOOL' ? false : 0)));
      this.listener?.status();
    }
    return Promise.resolve(true);
  }

  finalSafe(): Promise<boolean> {
    const acked = this.safe();
    this.final = true;
    return acked;
  }

  private writeOutputs(values: Values): void {
    const changed = new Map<string, WireValue>();
    for (const [address, value] of values) {
      if (!address.startsWith('%Q') || !this.values.has(address)) continue;
      if (this.values.get(address) !== value) changed.set(address, value);
      this.values.set(address, value);
    }
    if (changed.size) this.listener?.written(changed);
  }

  /** The machine in real time: its actuators are the %Q values (written by a Modbus master), its sensors set the %I values. */
  private startPlant(loop: PlantLoop): void {
    const io = {
      outputs: () => Object.fromEntries([...this.values].filter(([a]) => a.startsWith('%Q'))) as Record<string, Value>,
      setInputs: (values: Readonly<Record<string, Value>>) => {
        const map = new Map<string, WireValue>();
        for (const [address, value] of Object.entries(values)) {
          const key = [...this.values.keys()].find((a) => addressKey(a) === addressKey(address) && a.startsWith('%I'));
          if (key === undefined) throw new Error(`${address}: the simulated device has no such input`);
          map.set(key, typeof value === 'bigint' ? Number(value) : (value as WireValue));
        }
        this.setInputs(map);
      },
    };
    loop.bind(io);
    // The monotonic clock: a wall clock set forward or back (NTP, the user) must not leap or freeze the machine.
    const t0 = performance.now();
    let k = 0;
    let last = 0;
    this.plantTimer = setInterval(() => {
      const now = Math.round(performance.now() - t0);
      const events = loop.afterScan(++k, last, now - last);
      last = now;
      for (const e of events)
        this.log(`machine "${loop.model.id}": ${e.severity} ${e.message}, ${(e.timeMs / 1000).toFixed(1)} s after the gateway started`);
    }, PLANT_STEP_MS);
  }

  async close(): Promise<void> {
    clearTimeout(this.masterWatchdog);
    this.masterWatchdog = undefined;
    if (this.plantTimer) clearInterval(this.plantTimer);
    this.plantTimer = undefined;
    const server = this.server;
    this.server = undefined;
    if (!server) return;
    for (const sock of server.socks.keys()) sock.destroy();
    await new Promise<void>((resolve) => server.close(() => resolve()));
  }

  private read(table: DevicePoint['table'], register: number): WireValue {
    const p = this.byTable.get(`${table}:${register}`);
    if (p) return this.values.get(p.address) ?? 0;
    // Read-back of the input drive windows.
    if (table === 'coils' && register >= SIM_INPUT_COIL_BASE) return this.read('discreteInputs', register - SIM_INPUT_COIL_BASE);
    if (table === 'holdingRegisters' && register >= SIM_INPUT_REGISTER_BASE) return this.read('inputRegisters', register - SIM_INPUT_REGISTER_BASE);
    throw ILLEGAL_ADDRESS;
  }

  private driveInput(table: 'discreteInputs' | 'inputRegisters', register: number, value: WireValue): void {
    const p = this.byTable.get(`${table}:${register}`);
    if (!p) throw ILLEGAL_ADDRESS;
    // The machine writes its sensors' inputs only when they change: a value written over one would
    // stay, a limit switch ON with nothing behind it. Its operator controls may be pressed.
    if (this.machineSensorRefusal(p.address)) throw MACHINE_SENSOR;
    const button = this.plant?.points.find((q) => q.kind === 'operator' && q.control === 'button' && addressKey(q.address) === addressKey(p.address));
    if (button && value === true) this.buttonsHeld.add(p.address);
    else this.buttonsHeld.delete(p.address);
    this.simulateInputs(new Map([[p.address, value]]));
  }

  /**
   * A Modbus connection closed: with none left, the outputs the masters wrote fall OFF / 0, and the
   * push buttons held over Modbus spring back (an operator who let go; a switch stays as it was set).
   * Deferred one timer turn, after the requests that connection sent last (modbus-serial serves each
   * on a timer).
   */
  private masterGone(server: ModbusServer): void {
    const plant = this.plant;
    if (!plant) return;
    setTimeout(() => {
      if (this.server !== server || server.socks.size > 0) return;
      this.dropMasterOutputs('the Modbus master (the PLC) disconnected');
      if (this.buttonsHeld.size === 0) return;
      const released = [...this.buttonsHeld];
      this.buttonsHeld.clear();
      this.simulateInputs(new Map(released.map((a) => [a, false])));
      const keys = new Set(released.map(addressKey));
      const names = plant.points.filter((p) => keys.has(addressKey(p.address))).map((p) => p.name);
      this.log(`machine "${plant.model.id}": the last Modbus client disconnected holding ${names.join(', ')}; released (a push button springs back)`);
    }, 0);
  }

  /** A Modbus master wrote one of the machine's actuators: it is the PLC's output, and the watchdog is fed. */
  private masterWrote(address: string, value: WireValue): void {
    this.masterWritten.add(address);
    this.writeOutputs(new Map([[address, value]]));
    if (this.masterWatchdogMs <= 0) return;
    if (this.masterWatchdog) this.masterWatchdog.refresh();
    else {
      this.masterWatchdog = setTimeout(() => {
        this.masterWatchdog = undefined;
        this.dropMasterOutputs(
          `no write to its outputs from the Modbus master (the PLC) for ${this.masterWatchdogMs} ms (the device's communication watchdog, as an I/O coupler's; a PLC rewrites its outputs every cycle)`,
        );
      }, this.masterWatchdogMs);
      this.masterWatchdog.unref?.();
    }
  }

  /** The outputs the masters wrote fall OFF / 0, and the log says which and why (when one of them was on). */
  private dropMasterOutputs(why: string): void {
    const plant = this.plant;
    clearTimeout(this.masterWatchdog);
    this.masterWatchdog = undefined;
    if (!plant || this.masterWritten.size === 0) return;
    const off = new Map<string, WireValue>([...this.masterWritten].map((a) => [a, a.startsWith('%QX') ? false : 0]));
    const wasOn = [...off.keys()].some((a) => this.values.get(a) !== off.get(a));
    this.masterWritten.clear();
    this.writeOutputs(off);
    if (!wasOn) return;
    const keys = new Set([...off.keys()].map(addressKey));
    const names = plant.points.filter((p) => keys.has(addressKey(p.address))).map((p) => p.name);
    this.log(`machine "${plant.model.id}": ${why}; the outputs it wrote are OFF${names.length ? ` (${names.join(', ')})` : ''}`);
  }

  private startModbusServer(port: number): Promise<void> {
    const bit = (v: WireValue) => v === true;
    const word = (v: WireValue) => (typeof v === 'number' ? v & 0xffff : v ? 1 : 0);
    const vector = {
      getCoil: (addr: number) => bit(this.read('coils', addr)),
      getDiscreteInput: (addr: number) => bit(this.read('discreteInputs', addr)),
      getInputRegister: (addr: number) => word(this.read('inputRegisters', addr)),
      getHoldingRegister: (addr: number) => word(this.read('holdingRegisters', addr)),
      setCoil: (addr: number, value: boolean) => {
        // Virtual commissioning: the Modbus master is the PLC and drives the machine's actuators.
        const actuator = this.plant && addr < SIM_INPUT_COIL_BASE ? this.byTable.get(`coils:${addr}`) : undefined;
        if (actuator) {
          this.actuatorWrite(actuator.address, value);
          return;
        }
        if (addr < SIM_INPUT_COIL_BASE) throw this.byTable.has(`coils:${addr}`) ? ILLEGAL_FUNCTION : ILLEGAL_ADDRESS;
        this.driveInput('discreteInputs', addr - SIM_INPUT_COIL_BASE, value);
      },
      setRegister: (addr: number, value: number) => {
        // A machine's INT actuators (%QW) are the master's too, as its coils are.
        const actuator = this.plant && addr < SIM_INPUT_REGISTER_BASE ? this.byTable.get(`holdingRegisters:${addr}`) : undefined;
        if (actuator) {
          this.actuatorWrite(actuator.address, value & 0xffff);
          return;
        }
        if (addr < SIM_INPUT_REGISTER_BASE) throw this.byTable.has(`holdingRegisters:${addr}`) ? ILLEGAL_FUNCTION : ILLEGAL_ADDRESS;
        this.driveInput('inputRegisters', addr - SIM_INPUT_REGISTER_BASE, value & 0xffff);
      },
    };
    return new Promise((resolve, reject) => {
      const server = new ModbusServer(vector, { host: '127.0.0.1', port, unitID: 255 });
      this.server = server;
      const inner = (server as unknown as { _server: Server })._server;
      const fail = (err: Error) => reject(new Error(`simulated device: cannot listen on 127.0.0.1:${port} for Modbus TCP (${err.message})`));
      inner.once('error', fail);
      // modbus-serial forgets a socket (server.socks) in its own close listener, registered before this one.
      inner.on('connection', (sock: Socket) => {
        sock.once('close', () => this.masterGone(server));
        // Which master sent the request being served: modbus-serial parses each request on a timer
        // queued in its 'data' listener; this one runs first and queues the peer's name before it
        // (timers of one delay run in the order queued), so the name is set when the request is.
        const peer = `${sock.remoteAddress ?? '?'}:${sock.remotePort ?? '?'}`;
        sock.prependListener('data', () => {
          setTimeout(() => {
            this.peer = peer;
            this.requestSeq++;
          }, 0);
        });
      });
      inner.once('listening', () => {
        inner.off('error', fail);
        this.port = (inner.address() as AddressInfo).port;
        resolve();
      });
      server.on('socketError', () => undefined);
      server.on('serverError', () => undefined);
      server.on('error', () => undefined);
    });
  }
}
