"""The Numba pipeline of the kernel's stepping form (:func:`sarlink.engine.build.stepping_source`).

The stepping form is the kernel made a generator. Numba computes a generator's state (the
variables that live across a ``yield``) before it prunes the branches of the plug-in block's
constants (``RULE_DUE``, ``RULE_NEAR``), and then fails to type variables of the inlined hooks
that no longer exist ("Cannot type generator: state variable types cannot be found", seen with
ConB's kernel on Numba 0.68). This pipeline is Numba's own with one pass added: the state is
computed again just before type inference, from the IR that is typed.
"""

from __future__ import annotations

from typing import Any

from numba.core.compiler import CompilerBase, DefaultPassBuilder
from numba.core.compiler_machinery import FunctionPass, PassManager, register_pass
from numba.core.postproc import PostProcessor
from numba.core.typed_passes import NopythonTypeInference


@register_pass(mutates_CFG=False, analysis_only=False)
class GeneratorState(FunctionPass):
    """Recompute a generator's state variables from the IR as it is now."""

    _name = "sarlink_generator_state"

    def __init__(self) -> None:
        FunctionPass.__init__(self)

    def run_pass(self, state: Any) -> bool:
        if state.func_ir.is_generator:
            PostProcessor(state.func_ir).run()
        return False


class StepPipeline(CompilerBase):
    """Numba's nopython pipeline with :class:`GeneratorState` before type inference."""

    def define_pipelines(self) -> list[PassManager]:
        pm = DefaultPassBuilder.define_nopython_pipeline(self.state)
        at = [pass_ for pass_, _ in pm.passes].index(NopythonTypeInference)
        pm.passes.insert(at, (GeneratorState, "the generator's state, after pruning"))
        pm.finalize()
        return [pm]
