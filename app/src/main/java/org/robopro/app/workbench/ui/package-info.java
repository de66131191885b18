/**
 * The workbench window (Swing): the frame, menus and panels (jog, program, cell tree, properties,
 * calibration, robot wizard) as views over the session.
 */
package org.robopro.app.workbench.ui;
