/**
 * The wire protocol's vocabulary shared by client and simulator: open_abb's instruction numbers
 * and number formats, robopro's extensions, requests, replies and the CRC-32 checksum mode (TCP).
 */
package org.robopro.comms.protocol;
