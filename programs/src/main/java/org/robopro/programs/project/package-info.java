/**
 * The program project file ("robopro-program", JSON, docs/programs.md), read and written losslessly.
 */
package org.robopro.programs.project;
