/**
 * The link to a robot controller: commands (Command pattern) queued, retried and recorded by
 * {@link org.robopro.comms.CommandInvoker} over a {@link org.robopro.comms.connection.ControllerConnection}
 * (TCP or serial, or a simulator it starts), and measurement campaigns run through it
 * (docs/controller-link.md). The only module that talks to serial ports.
 */
package org.robopro.comms;
