/**
 * A connection to a controller, wired from the other packages: TCP or serial to a real controller
 * (or anything speaking open_abb), or a simulated controller this process starts as its own
 * process ({@link org.robopro.comms.connection.ControllerConnection}).
 */
package org.robopro.comms.connection;
