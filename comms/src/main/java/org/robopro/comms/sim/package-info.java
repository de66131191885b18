/**
 * A simulated controller speaking the protocol over TCP or a serial line, with a true robot
 * (errors, noise and injected effects) behind it, runnable in-process or as its own process
 * ({@link org.robopro.comms.sim.ControllerSim}). For tests, the demo and trying the tools
 * without a robot.
 */
package org.robopro.comms.sim;
