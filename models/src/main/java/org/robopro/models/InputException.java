package org.robopro.models;

/**
 * Bad user input: names the file, the line and column (0 when unknown), the field, and what is
 * wrong. Every reader of user files throws this and returns nothing half-built.
 */
public class InputException extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final String file;
    private final int line;
    private final int column;
    private final String field;
    private final String problem;

    public InputException(String file, int line, int column, String field, String problem) {
        super(format(file, line, column, field, problem));
        this.file = file;
        this.line = line;
        this.column = column;
        this.field = field;
        this.problem = problem;
    }

    public InputException(String file, int line, int column, String field, String problem, Throwable cause) {
        this(file, line, column, field, problem);
        initCause(cause);
    }

    private static String format(String file, int line, int column, String field, String problem) {
        StringBuilder sb = new StringBuilder(file == null ? "<input>" : file);
        if (line > 0) {
            sb.append(':').append(line);
            if (column > 0) sb.append(':').append(column);
        }
        sb.append(": ");
        if (field != null && !field.isEmpty()) sb.append("field '").append(field).append("': ");
        sb.append(problem);
        return sb.toString();
    }

    public String file() { return file; }
    public int line() { return line; }
    public int column() { return column; }
    public String field() { return field; }
    public String problem() { return problem; }
}
