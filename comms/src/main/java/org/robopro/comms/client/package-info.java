/**
 * The client side of the wire protocol: open_abb requests and robopro's extensions over a TCP
 * or serial request channel ({@link org.robopro.comms.client.ProtocolClient}).
 */
package org.robopro.comms.client;
