/**
 * The {@code robopro} application: the command line, the demo and the desktop workbench, all thin
 * front ends over the library modules. {@link org.robopro.app.Main} is the entry point.
 */
package org.robopro.app;
