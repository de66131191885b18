package org.robopro.programs;

/** One item at module level, kept in file order: data declaration, procedure or comment line. */
public sealed interface ModuleItem permits Declaration, Procedure, Comment, AstItem { }
