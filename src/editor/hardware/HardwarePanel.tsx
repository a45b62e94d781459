// The "Hardware" panel: link to the gateway, its devices and safety state, and the I/O points.
import { ConnectForm } from './ConnectForm';
import { GatewayStatus } from './GatewayStatus';
import { PointsTable } from './PointsTable';
import './hardware.css';

export function HardwarePanel() {
  return (
    <div className="rs-hw-panel" data-testid="hardware-panel">
      <ConnectForm />
      <GatewayStatus />
      <PointsTable />
    </div>
  );
}
