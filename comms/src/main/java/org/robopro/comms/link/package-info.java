/**
 * Reliable framing for serial lines: frames with CRC-16, acknowledgement, retransmission and
 * duplicate suppression ({@link org.robopro.comms.link.FramedLink}), over a byte link; and fault
 * injection for tests.
 */
package org.robopro.comms.link;
