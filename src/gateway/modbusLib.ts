// modbus-serial is CommonJS with the server hung off the default export; load it once, typed.
import { createRequire } from 'node:module';
import { createServer, type AddressInfo } from 'node:net';
import type ModbusRTU from 'modbus-serial';
import type { ServerTCP } from 'modbus-serial';

const lib = createRequire(import.meta.url)('modbus-serial') as typeof ModbusRTU & { ServerTCP: typeof ServerTCP };

export const ModbusClient = lib;
export type ModbusClient = ModbusRTU;
export const ModbusServer = lib.ServerTCP;
export type ModbusServer = ServerTCP;

/** A currently free loopback TCP port (modbus-serial's server treats port 0 as 502). */
export function freeLoopbackPort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const srv = createServer();
    srv.once('error', reject);
    srv.listen(0, '127.0.0.1', () => {
      const { port } = srv.address() as AddressInfo;
      srv.close(() => resolve(port));
    });
  });
}
