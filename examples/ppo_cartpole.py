#!/usr/bin/python3
"""PPO on manyworlds' cartpole-balance: proof that the environments learn.

    /usr/bin/python3 examples/ppo_cartpole.py                 # the README's run
    /usr/bin/python3 examples/ppo_cartpole.py --steps 200000  # shorter
    mpirun -n 2 /usr/bin/python3 examples/ppo_cartpole.py     # 2 MPI ranks

A plain PPO (Schulman et al. 2017, clipped objective) with generalised
advantage estimation, a Gaussian policy with a state-independent log
standard deviation, running observation normalisation and separate
policy and value MLPs, written with Debian's python3-torch (CPU). All
sub-environments step in one manyworlds batch (manyworlds.envs); the
trainer never loops over worlds in Python.

The task is dm_control's cartpole balance (docs/envs.md): 1000 steps of
0.01 s, reward in [0, 1] per step, so an episode's return is at most 1000.
"Solved" here means a mean return of at least 900 (--target) over a
deterministic evaluation (the policy's mean action) of --eval-envs fresh
episodes, twice in a row; a uniformly random policy scores about 280,
doing nothing about 370. The run stops once solved, or after --steps.

Under mpirun (docs/scale-out.md) the --envs worlds are sharded over the
ranks (envs.make(..., comm=MPI.COMM_WORLD)); every rank collects its
shard's rollouts and computes its gradients, which are averaged with an
allreduce before every optimiser step, as OpenAI Baselines' MPI PPO does.
The weights start equal (broadcast from rank 0) and so stay equal; the
observation statistics are reduced over all ranks; rank 0 evaluates, logs
and writes the curve. The same --envs over more ranks is the same
algorithm with the same samples per update, only spread out.

Writes (unless --out is empty) OUT.csv, the learning curve as numbers
(environment steps, wall seconds, mean training-episode return, evaluation
return), and OUT.png, the curve drawn with matplotlib when it is installed.
Exit code 0 when the target was reached, 1 when not, 2 for bad arguments.
"""

import argparse
import csv
import math
import sys
import time

import numpy as np
import torch
from torch import nn

import manyworlds
import manyworlds.envs as envs

ENV_ID = "cartpole-balance"


# -------------------------------------------------------------------- MPI


def mpi_comm():
    """MPI.COMM_WORLD when started by mpirun with more than one rank, else
    None (mpi4py is imported only then)."""
    import os
    if not any(v in os.environ for v in ("OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE")):
        return None
    from mpi4py import MPI
    return MPI.COMM_WORLD if MPI.COMM_WORLD.Get_size() > 1 else None


class Ranks:
    """The few collective operations the trainer needs; each is the identity
    without MPI (comm None), so the one-process run is unchanged."""

    def __init__(self, comm):
        self.comm = comm
        self.rank = comm.Get_rank() if comm else 0
        self.size = comm.Get_size() if comm else 1

    def sum(self, array):
        """Elementwise sum over ranks of a float64 numpy array."""
        if not self.comm:
            return array
        from mpi4py import MPI
        out = np.empty_like(array)
        self.comm.Allreduce(np.ascontiguousarray(array), out, op=MPI.SUM)
        return out

    def broadcast_parameters(self, model):
        """Rank 0's weights on every rank."""
        if not self.comm:
            return
        for parameter in model.parameters():
            values = parameter.data.numpy()
            self.comm.Bcast(values, root=0)

    def average_gradients(self, model, samples):
        """Every parameter's gradient replaced by the mean over ranks
        weighted by each rank's `samples` (its minibatch's size): the
        gradient of the loss over every rank's minibatch at once, also when
        shards differ in size. One allreduce of all gradients flattened
        together, the weight last."""
        if not self.comm:
            return
        grads = [p.grad for p in model.parameters()]
        flat = torch.cat([g.reshape(-1) for g in grads]).numpy().astype(np.float64)
        flat = self.sum(np.concatenate([flat * samples, [samples]]))
        flat = flat[:-1] / flat[-1]
        offset = 0
        for g in grads:
            g.copy_(torch.as_tensor(flat[offset:offset + g.numel()]).reshape(g.shape))
            offset += g.numel()

    def bcast(self, value):
        return self.comm.bcast(value, root=0) if self.comm else value

    def gather_lists(self, values):
        """Every rank's list, concatenated in rank order."""
        if not self.comm:
            return list(values)
        return [v for part in self.comm.allgather(list(values)) for v in part]


# ------------------------------------------------------------------- model


class RunningNormalizer:
    """Observation normalisation with a running mean and variance (Chan et
    al.'s parallel update), frozen during evaluation."""

    def __init__(self, size):
        self.mean = np.zeros(size, np.float64)
        self.var = np.ones(size, np.float64)
        self.count = 1e-4

    def update(self, batch, ranks=None):
        """Adds a batch [n, size]; with `ranks`, every rank's batch (the
        same statistics on every rank)."""
        if ranks is None or ranks.size == 1:
            batch_mean, batch_var, n = batch.mean(0), batch.var(0), batch.shape[0]
        else:
            sums = ranks.sum(np.concatenate([[batch.shape[0]], batch.sum(0)]).astype(np.float64))
            n, batch_mean = sums[0], sums[1:] / sums[0]
            batch_var = ranks.sum(((batch - batch_mean) ** 2).sum(0).astype(np.float64)) / n
        delta = batch_mean - self.mean
        total = self.count + n
        self.mean = self.mean + delta * n / total
        self.var = (self.var * self.count + batch_var * n
                    + delta ** 2 * self.count * n / total) / total
        self.count = total

    def __call__(self, obs):
        z = (obs - self.mean) / np.sqrt(self.var + 1e-8)
        return torch.as_tensor(np.clip(z, -10.0, 10.0), dtype=torch.float32)


def mlp(inputs, outputs, hidden, last_gain):
    layers = [nn.Linear(inputs, hidden), nn.Tanh(), nn.Linear(hidden, hidden), nn.Tanh(),
              nn.Linear(hidden, outputs)]
    # Orthogonal initialisation, small last layer (Andrychowicz et al. 2021,
    # "What matters in on-policy RL"): the first policy acts near zero.
    for layer in layers:
        if isinstance(layer, nn.Linear):
            nn.init.orthogonal_(layer.weight, math.sqrt(2.0))
            nn.init.zeros_(layer.bias)
    nn.init.orthogonal_(layers[-1].weight, last_gain)
    return nn.Sequential(*layers)


class ActorCritic(nn.Module):
    def __init__(self, observations, actions, hidden=64):
        super().__init__()
        self.policy = mlp(observations, actions, hidden, 0.01)
        self.value = mlp(observations, 1, hidden, 1.0)
        self.log_std = nn.Parameter(torch.full((actions,), -0.5))

    def distribution(self, obs):
        return torch.distributions.Normal(self.policy(obs), self.log_std.exp())


# ---------------------------------------------------------------- training


def evaluate(model, normalizer, episodes, seed, threads):
    """Mean return of `episodes` fresh episodes with the policy's mean action."""
    env = envs.make(ENV_ID, num_envs=episodes, threads=threads,
                    autoreset_mode=envs.AutoresetMode.DISABLED)
    obs, _ = env.reset(seed=seed)
    returns = np.zeros(episodes)
    done = np.zeros(episodes, np.bool_)
    with torch.no_grad():
        while not done.all():
            action = model.policy(normalizer(obs)).numpy()
            obs, reward, terminated, truncated, _ = env.step(action)
            returns += np.where(done, 0.0, reward)
            done |= terminated | truncated
    return float(returns.mean())


def random_policy_return(episodes, seed, threads):
    """Mean return of `episodes` episodes of uniformly random actions: the
    baseline a learner must clearly beat."""
    env = envs.make(ENV_ID, num_envs=episodes, threads=threads,
                    autoreset_mode=envs.AutoresetMode.DISABLED)
    env.reset(seed=seed)
    rng = np.random.default_rng(seed)
    returns = np.zeros(episodes)
    done = np.zeros(episodes, np.bool_)
    while not done.all():
        action = rng.uniform(-1.0, 1.0, (episodes, 1)).astype(np.float32)
        _, reward, terminated, truncated, _ = env.step(action)
        returns += np.where(done, 0.0, reward)
        done |= terminated | truncated
    return float(returns.mean())


def train(args, log=print, comm=None):
    """Trains until two evaluations in a row reach args.target or args.steps
    environment steps are done. Returns the learning curve: a list of
    (steps, seconds, mean training-episode return or nan, evaluation
    return or nan). With comm (mpi4py), the worlds are sharded over its
    ranks and gradients averaged; every rank returns the same curve."""
    ranks = Ranks(comm)
    torch.manual_seed(args.seed)
    # One torch thread: the networks are tiny (64 units), so intra-op
    # threads only add synchronisation, and on a busy core torch's spinning
    # workers slow it down tenfold.
    torch.set_num_threads(1)
    # SAME_STEP: an episode's last observation comes in info["final_obs"],
    # so a time-limit truncation can be bootstrapped with its value.
    env = envs.make(ENV_ID, num_envs=args.envs, threads=args.threads,
                    autoreset_mode=envs.AutoresetMode.SAME_STEP, comm=comm)
    n_obs = env.single_observation_space.shape[0]
    n_act = env.single_action_space.shape[0]
    model = ActorCritic(n_obs, n_act)
    ranks.broadcast_parameters(model)
    if ranks.size > 1:
        # Equal weights, but each rank its own action noise and minibatch
        # order: with one seed, every rank's worlds would explore alike.
        torch.manual_seed(args.seed + 7919 * ranks.rank)
    optimizer = torch.optim.Adam(model.parameters(), lr=args.lr, eps=1e-5)
    normalizer = RunningNormalizer(n_obs)

    obs, _ = env.reset(seed=args.seed)
    normalizer.update(obs, ranks)
    T, N = args.rollout, env.num_envs  # N: this rank's worlds
    buf_obs = torch.zeros(T, N, n_obs)
    buf_act = torch.zeros(T, N, n_act)
    buf_logp = torch.zeros(T, N)
    buf_rew = torch.zeros(T, N)
    buf_done = torch.zeros(T, N)  # the episode ended after this step (reset follows)
    buf_val = torch.zeros(T + 1, N)

    episode_return = np.zeros(N)
    finished = []
    curve = []
    steps = 0
    updates = 0
    start = time.perf_counter()
    while steps < args.steps:
        with torch.no_grad():
            for t in range(T):
                x = normalizer(obs)
                dist = model.distribution(x)
                action = dist.sample()
                buf_obs[t], buf_act[t] = x, action
                buf_logp[t] = dist.log_prob(action).sum(-1)
                buf_val[t] = model.value(x).squeeze(-1)
                obs, reward, terminated, truncated, info = env.step(action.numpy())
                episode_return += reward
                done = terminated | truncated
                reward = torch.as_tensor(reward, dtype=torch.float32)
                if truncated.any():
                    # Time limit, not failure: the return continues past the
                    # cut, so add the discounted value of the final state.
                    final = normalizer(info["final_obs"])
                    bootstrap = model.value(final).squeeze(-1)
                    cut = torch.as_tensor(truncated & ~terminated)
                    reward = reward + args.gamma * bootstrap * cut
                buf_rew[t] = reward
                buf_done[t] = torch.as_tensor(done, dtype=torch.float32)
                if done.any():
                    finished.extend(episode_return[done].tolist())
                    episode_return[done] = 0.0
                normalizer.update(obs, ranks)
            buf_val[T] = model.value(normalizer(obs)).squeeze(-1)

            # Generalised advantage estimation (Schulman et al. 2016).
            advantages = torch.zeros(T, N)
            running = torch.zeros(N)
            for t in reversed(range(T)):
                alive = 1.0 - buf_done[t]
                delta = buf_rew[t] + args.gamma * buf_val[t + 1] * alive - buf_val[t]
                running = delta + args.gamma * args.lam * alive * running
                advantages[t] = running
            returns = advantages + buf_val[:T]

        flat_obs, flat_act = buf_obs.reshape(T * N, n_obs), buf_act.reshape(T * N, n_act)
        flat_logp, flat_adv = buf_logp.reshape(-1), advantages.reshape(-1)
        flat_ret = returns.reshape(-1)
        batch = T * N
        for _ in range(args.epochs):
            # Exactly args.minibatches minibatches on every rank, whatever
            # its shard's size: each one ends in a collective gradient average.
            for idx in torch.tensor_split(torch.randperm(batch), args.minibatches):
                dist = model.distribution(flat_obs[idx])
                logp = dist.log_prob(flat_act[idx]).sum(-1)
                ratio = (logp - flat_logp[idx]).exp()
                adv = flat_adv[idx]
                adv = (adv - adv.mean()) / (adv.std() + 1e-8)
                policy_loss = -torch.min(
                    ratio * adv, ratio.clamp(1 - args.clip, 1 + args.clip) * adv).mean()
                value_loss = 0.5 * (model.value(flat_obs[idx]).squeeze(-1)
                                    - flat_ret[idx]).pow(2).mean()
                entropy = dist.entropy().sum(-1).mean()
                loss = policy_loss + args.value_coef * value_loss - args.entropy_coef * entropy
                optimizer.zero_grad()
                loss.backward()
                ranks.average_gradients(model, len(idx))
                nn.utils.clip_grad_norm_(model.parameters(), 0.5)
                optimizer.step()

        steps += T * env.global_num_envs  # every rank's worlds
        updates += 1
        recent = ranks.gather_lists(finished[-N:])
        train_return = float(np.mean(recent)) if recent else math.nan
        evaluation = math.nan
        if updates % args.eval_every == 0 or steps >= args.steps:
            # Rank 0 evaluates (the weights are the same everywhere).
            if ranks.rank == 0:
                evaluation = evaluate(model, normalizer, args.eval_envs,
                                      args.seed + 1000 + updates, args.threads)
            evaluation = ranks.bcast(evaluation)
        seconds = ranks.bcast(time.perf_counter() - start)
        curve.append((steps, seconds, train_return, evaluation))
        if ranks.rank == 0:
            log(f"steps {steps:8d}  {seconds:6.1f} s  training return {train_return:7.1f}"
                + ("" if math.isnan(evaluation) else f"  evaluation {evaluation:7.1f}"))
        evaluations = [row[3] for row in curve if not math.isnan(row[3])]
        if len(evaluations) >= 2 and min(evaluations[-2:]) >= args.target:
            break  # solved: two evaluations in a row at the target
    return curve


# -------------------------------------------------------------- the program


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--steps", type=int, default=2_000_000,
                        help="environment steps at most (default %(default)s)")
    parser.add_argument("--target", type=float, default=900.0,
                        help="evaluation return that counts as solved (default %(default)s)")
    parser.add_argument("--envs", type=int, default=64, help="worlds stepped together")
    parser.add_argument("--rollout", type=int, default=128, help="steps per world per update")
    parser.add_argument("--epochs", type=int, default=10)
    parser.add_argument("--minibatches", type=int, default=8)
    parser.add_argument("--lr", type=float, default=1e-3)
    parser.add_argument("--gamma", type=float, default=0.99)
    parser.add_argument("--lam", type=float, default=0.95)
    parser.add_argument("--clip", type=float, default=0.2)
    parser.add_argument("--value-coef", type=float, default=0.5)
    parser.add_argument("--entropy-coef", type=float, default=0.0)
    parser.add_argument("--eval-every", type=int, default=2, help="updates between evaluations")
    parser.add_argument("--eval-envs", type=int, default=32, help="episodes per evaluation")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=1,
                        help="threads of the batch (0: every core; 64 cartpoles need one)")
    parser.add_argument("--out", default="ppo_cartpole",
                        help="OUT.csv and OUT.png (the learning curve); '' writes nothing")
    args = parser.parse_args(argv)
    for name in ("steps", "envs", "rollout", "epochs", "minibatches", "eval_every", "eval_envs"):
        if getattr(args, name) < 1:
            parser.error(f"--{name.replace('_', '-')}: expected >= 1, got {getattr(args, name)}")
    if args.threads < 0:
        parser.error(f"--threads: expected >= 0, got {args.threads}")
    if args.envs * args.rollout < 2 * args.minibatches:
        parser.error("--minibatches: fewer than two samples per minibatch")
    return args


def write_curve(curve, out, target, random_return):
    with open(out + ".csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["steps", "seconds", "training_return", "evaluation_return"])
        writer.writerows(curve)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return [out + ".csv"]
    steps = np.array([row[0] for row in curve])
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
    ax.plot(steps, [row[2] for row in curve], label="training episodes (stochastic, lagging)")
    evaluated = [(row[0], row[3]) for row in curve if not math.isnan(row[3])]
    if evaluated:
        ax.plot(*zip(*evaluated), "o-", label="evaluation (mean action)")
    ax.axhline(target, color="gray", linestyle="--", linewidth=1, label=f"target {target:g}")
    ax.axhline(random_return, color="gray", linestyle=":", linewidth=1,
               label=f"random policy {random_return:.0f}")
    ax.set_xlabel("environment steps")
    ax.set_ylabel("episode return (max 1000)")
    ax.set_ylim(0, 1050)
    ax.set_title(f"PPO on manyworlds {ENV_ID}, {curve[-1][1]:.0f} s wall")
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(out + ".png")
    return [out + ".csv", out + ".png"]


def main(argv=None, comm=None):
    args = parse_args(argv)
    ranks = Ranks(comm)
    # Every rank needs a world, and two samples for every minibatch (one
    # sample has no standard deviation to normalise its advantage by).
    smallest = min(manyworlds.shard_of_worlds(args.envs, r, ranks.size)[1]
                   for r in range(ranks.size)) if args.envs >= ranks.size else 0
    if smallest * args.rollout < 2 * args.minibatches:
        if ranks.rank == 0:
            print(f"--envs {args.envs} over {ranks.size} ranks: the smallest shard has "
                  f"{smallest} worlds, {smallest * args.rollout} samples per update, fewer than "
                  f"two for each of --minibatches {args.minibatches}", file=sys.stderr)
        return 2
    random_return = ranks.bcast(random_policy_return(args.eval_envs, args.seed, args.threads)
                                if ranks.rank == 0 else None)
    if ranks.rank == 0:
        where = f" over {ranks.size} MPI ranks" if comm else ""
        print(f"{ENV_ID}: {args.envs} worlds{where}, random policy return {random_return:.1f}")
    curve = train(args, comm=comm)
    if ranks.rank != 0:
        return 0 if _solved(curve, args.target) else 1
    solved = _solved(curve, args.target)
    evaluations = [row[3] for row in curve if not math.isnan(row[3])]
    print(f"{'solved' if solved else 'not solved'}: {curve[-1][0]} steps in "
          f"{curve[-1][1]:.1f} s, last evaluation returns "
          + ", ".join(f"{e:.1f}" for e in evaluations[-2:])
          + f" (target {args.target:g}, random {random_return:.1f})")
    if args.out:
        print("wrote " + ", ".join(write_curve(curve, args.out, args.target, random_return)))
    return 0 if solved else 1


def _solved(curve, target):
    evaluations = [row[3] for row in curve if not math.isnan(row[3])]
    return len(evaluations) >= 2 and min(evaluations[-2:]) >= target


if __name__ == "__main__":
    comm = mpi_comm()
    try:
        code = main(comm=comm)
    except SystemExit:
        raise  # argparse's usage errors: the same on every rank, exit code 2
    except BaseException:
        # Under mpirun one rank's exception would leave the others waiting
        # in their next collective call forever: end them all.
        if comm is not None:
            import traceback
            traceback.print_exc()
            sys.stderr.flush()
            comm.Abort(1)
        raise
    sys.exit(code)
