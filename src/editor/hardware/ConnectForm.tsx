// Gateway URL, token and role; Connect / Disconnect.
import { useState } from 'react';
import { tokenFromFragment } from '../../bridge/connection';
import { gatewayLink } from '../../bridge/gatewayLink';
import type { Role } from '../../protocol/messages';
import { useSimStore } from '../sim/simContext';
import { useGateway } from './useGateway';

/** Opened from the gateway (token in the fragment): the gateway is this page's origin. */
function defaults(): { url: string; token: string } {
  const token = tokenFromFragment(window.location.hash);
  return { url: token ? window.location.origin + '/' : 'http://127.0.0.1:8080/', token: token ?? '' };
}

const LINK_WORDS = { idle: 'Not connected', connecting: 'Connecting…', open: 'Connected', retrying: 'Connection lost', refused: 'Refused' } as const;

export function ConnectForm() {
  const view = useGateway();
  useSimStore(); // the link's socket lives in the simulation worker: make sure it exists
  const [initial] = useState(defaults);
  const [url, setUrl] = useState(initial.url);
  const [token, setToken] = useState(initial.token);
  const [role, setRole] = useState<Role>('controller');
  const [formError, setFormError] = useState<string | null>(null);
  const linked = view.link !== 'idle' && view.link !== 'refused';

  const connect = () => setFormError(gatewayLink.connect({ gatewayUrl: url, token, role }));

  return (
    <form
      className="rs-hw-form"
      onSubmit={(e) => {
        e.preventDefault();
        if (linked) gatewayLink.disconnect();
        else connect();
      }}
    >
      <label>
        Gateway URL
        <input value={url} onChange={(e) => setUrl(e.target.value)} disabled={linked} spellCheck={false} data-testid="hw-url" />
      </label>
      <label>
        Token
        <input type="password" value={token} onChange={(e) => setToken(e.target.value)} disabled={linked} autoComplete="off" data-testid="hw-token" />
      </label>
      <label>
        Role
        <select value={role} onChange={(e) => setRole(e.target.value as Role)} disabled={linked} data-testid="hw-role">
          <option value="controller">Controller (writes outputs)</option>
          <option value="observer">Observer (read only)</option>
        </select>
      </label>
      <div className="rs-hw-row">
        <button type="submit" className="rs-hw-primary" data-testid="hw-connect">
          {linked ? 'Disconnect' : view.link === 'refused' ? 'Reconnect' : 'Connect'}
        </button>
        <span className={`rs-hw-link rs-hw-link-${view.link}`} data-testid="hw-link" role="status">
          {LINK_WORDS[view.link]}
          {view.link === 'open' && view.role ? ` as ${view.role}` : ''}
        </span>
      </div>
      {(formError ?? view.problem) && (
        <p className="rs-hw-problem" role="alert" data-testid="hw-problem">
          {formError ?? view.problem}
        </p>
      )}
    </form>
  );
}
