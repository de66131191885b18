/**
 * The desktop workbench: the headless session with every operation
 * ({@link org.robopro.app.workbench.WorkbenchSession}, testable without a display), the controller
 * session and the project file. The window and the 3D view are in the sub-packages.
 */
package org.robopro.app.workbench;
