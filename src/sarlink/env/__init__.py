"""sarlink as a multi-agent environment for learning planners (PettingZoo, Gymnasium spaces).

Needs the ``rl`` extra: ``pip install "sarlink[rl]"``. The environment runs the engine's own
kernel in its stepping form (:mod:`sarlink.env.episode`): the decisions come from the agents,
everything else is the model ``sarlink simulate`` runs (docs/env.md).
"""

try:
    import gymnasium  # noqa: F401
    import pettingzoo  # noqa: F401
except ImportError as exc:  # pragma: no cover - depends on the installation
    raise ImportError('sarlink.env needs the rl extra: pip install "sarlink[rl]"') from exc

from sarlink.env.batch import BatchEnv
from sarlink.env.episode import EngineState, Episode
from sarlink.env.features import NEIGHBOUR, OWN, feature_names
from sarlink.env.parallel import SarlinkParallelEnv, env, parallel_env
from sarlink.env.rewards import Rewards

__all__ = ["NEIGHBOUR", "OWN", "BatchEnv", "EngineState", "Episode", "Rewards",
           "SarlinkParallelEnv", "env", "feature_names", "parallel_env"]
