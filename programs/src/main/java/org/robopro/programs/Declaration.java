package org.robopro.programs;

import org.robopro.programs.rapid.RapidAst.Scope;
import org.robopro.programs.rapid.RapidAst.Storage;

/**
 * A module-level data declaration: {@code [LOCAL|TASK] CONST|PERS|VAR type name := value;}.
 */
public record Declaration(Scope scope, Storage storage, String name, RapidValue value) implements ModuleItem {
    public Declaration {
        if (scope == null || storage == null || name == null || name.isEmpty() || value == null)
            throw new IllegalArgumentException("declaration fields must not be null");
    }

    public static Declaration constant(String name, RapidValue value) { return new Declaration(Scope.GLOBAL, Storage.CONST, name, value); }

    public static Declaration pers(String name, RapidValue value) { return new Declaration(Scope.GLOBAL, Storage.PERS, name, value); }

    public static Declaration var(String name, RapidValue value) { return new Declaration(Scope.GLOBAL, Storage.VAR, name, value); }

    public String rapidType() { return value.rapidType(); }

    public Declaration withName(String newName) { return new Declaration(scope, storage, newName, value); }

    public Declaration withValue(RapidValue newValue) { return new Declaration(scope, storage, name, newValue); }
}
