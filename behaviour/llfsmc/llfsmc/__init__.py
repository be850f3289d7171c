"""llfsmc: the LLFSM model compiler (behaviour/README.md describes the model format).

Modules, in the order a model goes through them:
  source       reads the model (a bounded read, strict UTF-8) and the whiteboard schema
  lexer        tokens of model lines (guards, types, initial values) and C++ action blocks
  expr_parser  guard / initial-value expressions and C++ types -> syntax trees (syntax.py)
  model_parser the line-oriented .machine format -> model.Model
  check        the semantic rules (states, identifiers, guards against the declarations)
  emit_cpp, emit_dot   the outputs
  cli          the command line; every error is `FILE:LINE:COL: error: message`
"""
