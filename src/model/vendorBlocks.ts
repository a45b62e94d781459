// Interfaces of the vendor library blocks OpenPLC Editor ships (its editor/plcopen/*.xml
// libraries: communication, MQTT, Arduino, P1AM, Sequent Microsystems cards, Jaguar, SL-RP4,
// STM32 CAN, I2C sensors). Only the interface facts are kept: name, kind, pin names, directions and
// types in declaration order, and a one-line description. The libraries declare no initial
// values, so every pin starts at its type's default. A simulator cannot talk MQTT or drive a
// P1AM module: these blocks run as external blocks (externalBlocks.ts).
//
// Pin lists are written `NAME:TYPE`, separated by spaces; `O{1..8}:BOOL` stands for O1 ... O8.
// Types Rungsmith does not have (STRING) are kept as declared.
import type { ExternalBlock, ExternalBlockPin } from './project';

export interface VendorLibrary {
  /** The library's name as OpenPLC Editor's library tree shows it. */
  readonly name: string;
  /** The OpenPLC Editor file it comes from. */
  readonly file: string;
  readonly blocks: readonly ExternalBlock[];
}

export const VENDOR = 'OpenPLC';

const RANGE = /\{(\d+)\.\.(\d+)\}/;

function pins(spec: string, dir: ExternalBlockPin['dir']): ExternalBlockPin[] {
  return spec
    .split(/\s+/)
    .filter(Boolean)
    .flatMap((item) => {
      const [name = '', type = ''] = item.split(':');
      const range = RANGE.exec(name);
      if (!range) return [{ name, dir, type }];
      const from = Number(range[1]);
      const to = Number(range[2]);
      return Array.from({ length: to - from + 1 }, (_, i) => ({ name: name.replace(RANGE, String(from + i)), dir, type }));
    });
}

const library = (name: string, file: string, blocks: readonly [string, string, string, string][]): VendorLibrary => ({
  name,
  file,
  blocks: blocks.map(([block, inputs, outputs, comment]) => ({
    name: block,
    kind: 'FUNCTION_BLOCK',
    pins: [...pins(inputs, 'in'), ...pins(outputs, 'out')],
    library: name,
    vendor: VENDOR,
    comment,
  })),
});

// [name, inputs, outputs, description]; all are function blocks.
export const VENDOR_LIBRARIES: readonly VendorLibrary[] = [
  library('Communication', 'Communication_Blocks.xml', [
    ['TCP_CONNECT', 'CONNECT:BOOL IP_ADDRESS:STRING PORT:INT', 'SOCKET_ID:INT', 'Opens a TCP connection to IP_ADDRESS:PORT while CONNECT is TRUE; SOCKET_ID is the connection id, below zero on failure.'],
    ['TCP_SEND', 'SEND:BOOL SOCKET_ID:INT MSG:STRING', 'BYTES_SENT:INT', 'Sends MSG over connection SOCKET_ID while SEND is TRUE; BYTES_SENT is the byte count, below zero on error.'],
    ['TCP_RECEIVE', 'RECEIVE:BOOL SOCKET_ID:INT', 'BYTES_RECEIVED:INT MSG:STRING', 'Reads from connection SOCKET_ID while RECEIVE is TRUE; BYTES_RECEIVED is the byte count and MSG the text received.'],
    ['TCP_CLOSE', 'CLOSE:BOOL SOCKET_ID:INT', 'SUCCESS:INT', 'Closes connection SOCKET_ID; SUCCESS is below zero when it could not be closed or no longer exists.'],
  ]),
  library('MQTT', 'MQTT.xml', [
    ['MQTT_CONNECT', 'CONNECT:BOOL BROKER:STRING PORT:UINT', 'SUCCESS:BOOL', 'Connects to the MQTT BROKER at PORT when CONNECT is TRUE; SUCCESS tells the connection was made.'],
    ['MQTT_CONNECT_AUTH', 'CONNECT:BOOL BROKER:STRING PORT:UINT USER:STRING PASSWORD:STRING', 'SUCCESS:BOOL', 'Connects to an MQTT BROKER at PORT with USER and PASSWORD when CONNECT is TRUE; SUCCESS tells the connection was made.'],
    ['MQTT_DISCONNECT', 'DISCONNECT:BOOL', 'SUCCESS:BOOL', 'Disconnects from the MQTT broker when DISCONNECT is TRUE; SUCCESS tells it was done.'],
    ['MQTT_SEND', 'SEND:BOOL TOPIC:STRING MESSAGE:STRING', 'SUCCESS:BOOL', 'Publishes MESSAGE to TOPIC on every scan while SEND is TRUE (not edge-triggered); SUCCESS tells it was sent.'],
    ['MQTT_RECEIVE', 'RECEIVE:BOOL TOPIC:STRING', 'RECEIVED:BOOL MESSAGE:STRING', 'Takes a message of a subscribed TOPIC from the message pool while RECEIVE is TRUE; RECEIVED tells one came, MESSAGE holds it.'],
    ['MQTT_SUBSCRIBE', 'SUBSCRIBE:BOOL TOPIC:STRING', 'SUCCESS:BOOL', 'Subscribes to TOPIC when SUBSCRIBE is TRUE; messages then queue in a pool of 10 for MQTT_RECEIVE.'],
    ['MQTT_UNSUBSCRIBE', 'UNSUBSCRIBE:BOOL TOPIC:STRING', 'SUCCESS:BOOL', 'Unsubscribes from TOPIC when UNSUBSCRIBE is TRUE; SUCCESS tells it was done.'],
  ]),
  library('P1AM', 'P1AM.xml', [
    ['P1AM_INIT', 'INIT:BOOL', 'SUCCESS:SINT', 'Initialises the P1AM modules; SUCCESS is the number of modules found, 0 on error or an empty bus.'],
    ['P1_16CDR', 'SLOT:SINT O{1..8}:BOOL', 'I{1..8}:BOOL', 'Reads the inputs and sets the outputs of a P1-16CDR module in SLOT (also P1-15CDD1, P1-15CDD2).'],
    ['P1_08N', 'SLOT:SINT', 'I{1..8}:BOOL', 'Reads the inputs of a P1-08Nxx module in SLOT (P1-08NA, P1-08ND3, P1-08NE3, P1-08SIM).'],
    ['P1_16N', 'SLOT:SINT', 'I{1..16}:BOOL', 'Reads the inputs of a P1-16Nxx module in SLOT (P1-16ND3, P1-16NE3).'],
    ['P1_08T', 'SLOT:SINT O{1..8}:BOOL', '', 'Sets the outputs of a P1-08Txx module in SLOT (P1-08TA, P1-08TD1, P1-08TD2, P1-08TRS).'],
    ['P1_16TR', 'SLOT:SINT O{1..16}:BOOL', '', 'Sets the outputs of a P1-16TR module in SLOT (also P1-15TD1, P1-15TD2).'],
    ['P1_04AD', 'SLOT:SINT', 'I{1..4}:UINT', 'Reads the analog inputs of a P1-04ADxx module in SLOT (P1-04AD, P1-04ADL-1, P1-04ADL-2).'],
  ]),
  library('Arduino', 'Arduino_Function_Blocks.xml', [
    ['DS18B20', 'PIN:SINT', 'OUT:REAL', 'Reads the temperature (Celsius) of one DS18B20 one-wire sensor on PIN.'],
    ['DS18B20_2_OUT', 'PIN:SINT', 'OUT_{0..1}:REAL', 'Reads the temperatures (Celsius) of two DS18B20 sensors on the one-wire bus at PIN.'],
    ['DS18B20_3_OUT', 'PIN:SINT', 'OUT_{0..2}:REAL', 'Reads the temperatures (Celsius) of three DS18B20 sensors on the one-wire bus at PIN.'],
    ['DS18B20_4_OUT', 'PIN:SINT', 'OUT_{0..3}:REAL', 'Reads the temperatures (Celsius) of four DS18B20 sensors on the one-wire bus at PIN.'],
    ['DS18B20_5_OUT', 'PIN:SINT', 'OUT_{0..4}:REAL', 'Reads the temperatures (Celsius) of five DS18B20 sensors on the one-wire bus at PIN.'],
    ['CLOUD_BEGIN', 'THING_ID:STRING SSID:STRING PASS:STRING', '', 'Sets up Arduino IoT Cloud communication; call it before adding cloud variables.'],
    ['CLOUD_ADD_BOOL', 'VAR_NAME:STRING BOOL_VAR:BOOL', '', 'Syncs a BOOL variable with the Arduino IoT Cloud variable named VAR_NAME.'],
    ['CLOUD_ADD_DINT', 'VAR_NAME:STRING DINT_VAR:DINT', '', 'Syncs a DINT variable with the Arduino IoT Cloud variable named VAR_NAME.'],
    ['CLOUD_ADD_REAL', 'VAR_NAME:STRING REAL_VAR:REAL', '', 'Syncs a REAL variable with the Arduino IoT Cloud variable named VAR_NAME.'],
    ['PWM_CONTROLLER', 'CHANNEL:SINT FREQ:REAL DUTY:REAL', 'SUCCESS:BOOL', 'Drives the hardware PWM of CHANNEL at FREQ Hz with DUTY percent (0-100).'],
    ['ARDUINOCAN_CONF', 'EN_PIN:WORD BR:LINT', 'DONE:BOOL', 'Configures the Arduino CAN bus: enable pin EN_PIN, baud rate BR; DONE when configured.'],
    ['ARDUINOCAN_WRITE', 'ID:DWORD D{0..7}:USINT', 'DONE:BOOL', 'Sends a CAN message ID with payload bytes D0-D7; DONE when written.'],
    ['ARDUINOCAN_WRITE_WORD', 'ID:DWORD DATA:LWORD', 'DONE:BOOL', 'Sends a CAN message ID with the 8-byte payload DATA; DONE when written.'],
    ['ARDUINOCAN_READ', '', 'DATA:LWORD', 'Reads the payload of a received CAN message into DATA.'],
  ]),
  library('I2C sensors', 'I2C_SENSOR.xml', [
    ['I2C_THREMO_4_OUT', 'ADDR_SLAVE:SINT', 'OUT_{0..3}:REAL', 'Reads four temperatures (Celsius) from the I2C module at ADDR_SLAVE.'],
  ]),
  library('Jaguar', 'Jaguar.xml', [
    ['ADC_CONFIG', 'ADC_CH:SINT ADC_TYPE:SINT', 'SUCCESS:BOOL', 'Configures Jaguar analog input ADC_CH (0-3) as ADC_TYPE 0-3: unipolar 10 V, bipolar 10 V, unipolar 5 V, bipolar 5 V.'],
  ]),
  library('SL-RP4', 'SL-RP4.xml', [
    ['ROTARY_SWITCH', 'READ:BOOL', 'ERROR:BOOL OUT:INT', 'Reads the SL-RP4 rotary switch position into OUT when READ is TRUE; ERROR tells the read failed.'],
  ]),
  library('Sequent Microsystems cards', 'SM_Cards.xml', [
    ['SM_8RELAY', 'STACK:SINT O{1..8}:BOOL', '', 'Sets the 8 relays of the card at STACK.'],
    ['SM_16RELAY', 'STACK:SINT O{1..16}:BOOL', '', 'Sets the 16 relays of the card at STACK.'],
    ['SM_8DIN', 'STACK:SINT', 'I{1..8}:BOOL', 'Reads the 8 high-voltage inputs of the card at STACK.'],
    ['SM_16DIN', 'STACK:SINT', 'I{1..16}:BOOL', 'Reads the 16 digital inputs of the card at STACK.'],
    ['SM_4REL4IN', 'STACK:SINT RELAY{1..4}:BOOL', 'OPTO{1..4}:BOOL AC_OPTO{1..4}:BOOL PWM{1..4}:REAL FREQ{1..4}:UINT BUTTON:BOOL', 'Sets the 4 relays and reads the inputs of a 4-relay 4-input card at STACK.'],
    [
      'SM_INDUSTRIAL',
      'STACK:SINT LED{1..4}:BOOL Q0_10V{1..4}:REAL Q4_20MA{1..4}:REAL QOD{1..4}:REAL',
      'OPTO{1..4}:BOOL I0_10V{1..4}:REAL I4_20MA{1..4}:REAL OWB_T{1..4}:REAL',
      'Reads the inputs and sets the outputs of an Industrial Automation card at STACK.',
    ],
    ['SM_RTD', 'STACK:SINT', 'TEMP{1..8}:REAL', 'Reads the 8 RTD temperatures (Celsius) of the card at STACK.'],
    [
      'SM_BAS',
      'STACK:SINT TRIAC{1..4}:BOOL LED{1..4}:BOOL IN{1..8}_T:UINT Q0_10V{1..4}:REAL',
      'UNIV{1..8}:REAL DRY_C{1..8}:BOOL OWB_T{1..4}:REAL',
      'Reads the inputs and sets the outputs of a Building Automation card at STACK.',
    ],
    [
      'SM_HOME',
      'STACK:SINT RELAY{1..8}:BOOL Q0_10V{1..4}:REAL QOD{1..4}:REAL',
      'OPTO{1..8}:BOOL ADC{1..8}:REAL OWB_T{1..4}:REAL',
      'Reads the inputs and sets the outputs of a Home Automation card at STACK.',
    ],
    ['SM_8MOSFET', 'STACK:SINT MOS{1..8}:BOOL', '', 'Sets the 8 MOSFET outputs of the card at STACK.'],
  ]),
  library('STM32 CAN', 'STM32_Function_Blocks.xml', [
    ['STM32CAN_CONF', 'CONF:BOOL BR:LINT', 'DONE:BOOL', 'Configures the STM32 CAN bus at baud rate BR when CONF is TRUE; DONE when configured.'],
    ['STM32CAN_WRITE', 'EN_PIN:BOOL CH:USINT ID:DWORD D{0..7}:BYTE', 'DONE:BOOL', 'Sends a CAN message ID with payload bytes D0-D7 on channel CH; DONE when written.'],
    ['STM32CAN_READ', 'EN_PIN:BOOL', 'DONE:BOOL ID:DWORD D{0..7}:BYTE', 'Reads a received CAN message: its ID and payload bytes D0-D7; DONE when one was read.'],
  ]),
];

/** Every shipped vendor block, library by library. */
export const VENDOR_BLOCKS: readonly ExternalBlock[] = VENDOR_LIBRARIES.flatMap((l) => l.blocks);

const BY_NAME = new Map(VENDOR_BLOCKS.map((b) => [b.name.toUpperCase(), b]));

/** A shipped vendor block by (case-insensitive) name. */
export const vendorBlock = (name: string): ExternalBlock | undefined => BY_NAME.get(name.trim().toUpperCase());
