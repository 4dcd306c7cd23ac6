"""Type stubs of the extension module kinsyn._native (the reports are JSON text; the package
``kinsyn`` turns them into DataFrames and arrays)."""

from os import PathLike
from typing import List, Optional, Union

class KinsynError(Exception): ...
class InputError(KinsynError): ...

def catalogue_json() -> str: ...
def query_json(pattern: str, max_locks: int = 6, family: Optional[str] = None) -> str: ...
def solve_json(
    text: str,
    source: str = "<string>",
    seed: int = 1,
    start: str = "auto",
    runs: int = 1,
    threads: Optional[int] = None,
    certify: bool = True,
) -> str: ...
def solve_file_json(
    path: Union[str, PathLike[str]],
    seed: int = 1,
    start: str = "auto",
    runs: int = 1,
    threads: Optional[int] = None,
    certify: bool = True,
) -> str: ...
def solve_shard_json(
    path: Union[str, PathLike[str]],
    shard: int,
    shards: int,
    out: Union[str, PathLike[str]],
    seed: int = 1,
    start: str = "auto",
    threads: Optional[int] = None,
    force: bool = False,
) -> str: ...
def merge_shards_json(
    path: Union[str, PathLike[str]],
    parts: List[Union[str, PathLike[str]]],
    seed: int = 1,
    start: str = "auto",
    threads: Optional[int] = None,
    certify: bool = True,
) -> str: ...

def configurable_inverse_json(
    theta: float, phi: float, centre: Optional[str] = None, c4: Optional[str] = None
) -> str: ...
def configurable_forward_json(q: str, method: int = 2) -> str: ...
def configurable_velocity_json(q: str, qdot: str, near: Optional[str] = None) -> str: ...
def components_json(
    path: Union[str, PathLike[str]],
    inputs: Optional[str] = None,
    free_inputs: bool = False,
    method: str = "by-dimension",
    seed: int = 1,
    max_paths: Optional[int] = None,
    free: Optional[str] = None,
    body: Optional[str] = None,
) -> str: ...
def sweep_json(
    out: Union[str, PathLike[str]],
    legs: int = 3,
    actuated: List[int] = ...,
    seed: Optional[int] = None,
    chains: Optional[List[str]] = None,
    family: Optional[str] = None,
    shard: Optional[str] = None,
    threads: Optional[int] = None,
    stop_after: Optional[int] = None,
    force: bool = False,
) -> str: ...
def sweep_merge_json(
    dirs: List[Union[str, PathLike[str]]], out: Union[str, PathLike[str]], force: bool = False
) -> str: ...
def sweep_partitions_json(
    count: int,
    legs: int = 3,
    actuated: List[int] = ...,
    seed: Optional[int] = None,
    chains: Optional[List[str]] = None,
    family: Optional[str] = None,
) -> str: ...
def sweep_rows_json(path: Union[str, PathLike[str]]) -> str: ...
def sweep_check_table(path: Union[str, PathLike[str]]) -> None: ...
def sweep_table_rows_json(path: Union[str, PathLike[str]], rows: str) -> str: ...

class Manipulator:
    @staticmethod
    def from_file(path: Union[str, PathLike[str]]) -> Manipulator: ...
    @staticmethod
    def from_json(text: str, source: str = "<string>") -> Manipulator: ...
    @staticmethod
    def build(
        chain: str,
        legs: int = 3,
        actuated: Optional[List[int]] = None,
        axes: Optional[str] = None,
        base_radius: float = 1.0,
        platform_radius: float = 0.5,
        height: float = 1.0,
        twist: float = 0.0,
        alternate: bool = False,
        name: Optional[str] = None,
    ) -> Manipulator: ...
    @property
    def name(self) -> str: ...
    @property
    def inputs(self) -> List[str]: ...
    def to_json(self) -> str: ...
    def analyze_json(
        self,
        pose: Optional[str] = None,
        inputs: Optional[str] = None,
        lock: Optional[str] = None,
        seed: int = 2026,
        body: Optional[str] = None,
        relative_to: Optional[str] = None,
        study: List[str] = ...,
    ) -> str: ...
    def modes_json(
        self,
        max_locks: Optional[int] = None,
        lock: Optional[str] = None,
        pose: Optional[str] = None,
        max_subsets: int = 4096,
        seed: int = 2026,
        samples: int = 3,
        body: Optional[str] = None,
        relative_to: Optional[str] = None,
        legs: Optional[str] = None,
    ) -> str: ...
    def assemblies_json(self, inputs: Optional[str] = None, seed: int = 2026) -> str: ...
    def view_html(
        self,
        inputs: Optional[str] = None,
        steps: int = 16,
        assemblies: bool = True,
        components: bool = False,
        free_inputs: bool = False,
        max_paths: int = 65536,
        seed: int = 1,
    ) -> str: ...
