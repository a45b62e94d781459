// npm run test:interop — OpenPLC Editor's own examples (GPL, in the corpus outside the repository)
// call its vendor library blocks: every one is known, with every pin the file wires. The same on
// a fixture of the repository: tests/model/vendorBlocks.test.ts.
import { test } from 'vitest';
import { expectVendorCallsKnown } from '../model/vendorCalls';
import { corpusText } from './corpusDir';

test.each([
  ['openplc-editor__MQTT_Send_Receive.xml', ['MQTT_CONNECT', 'MQTT_RECEIVE', 'MQTT_SEND', 'MQTT_SUBSCRIBE']],
  ['openplc-editor__TCP_socket.xml', ['TCP_CONNECT', 'TCP_RECEIVE', 'TCP_SEND']],
  ['openplc-editor__Blink_P1AM.xml', ['P1AM_INIT', 'P1_16CDR']],
])('%s: every block it calls from an OpenPLC library is known, with every pin it wires', (file, expected) => {
  expectVendorCallsKnown(corpusText(file), expected);
});
