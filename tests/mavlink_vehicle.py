"""A vehicle stand-in for upload tests: a minimal MAVLink mission-protocol responder written
with pymavlink, joined to MAVSDK in process through MAVSDK's ``raw://`` connection.

MAVSDK sends its bytes to :meth:`Vehicle.receive` (from its own thread); the vehicle's thread
parses them with pymavlink, sends heartbeats as a PX4 or ArduPilot autopilot, and answers a
mission upload as the MAVLink mission protocol says (https://mavlink.io/en/services/mission.html):
``MISSION_COUNT`` -> ``MISSION_REQUEST_INT`` for each item in turn -> ``MISSION_ACK``. What
it received is kept, item by item, for the test to compare with the route.
"""

from __future__ import annotations

import queue
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from mavsdk import ComponentType, Configuration, Mavsdk
from mavsdk.plugins.mission_raw import MissionRaw
from pymavlink.dialects.v20 import common as mav  # MAVLink 2: MISSION_ITEM_INT, mission types

HEARTBEAT_PERIOD = 0.2
"""Seconds between the vehicle's heartbeats (MAVSDK finds a system by its heartbeat)."""
TIMEOUT = 10.0
"""Seconds to wait for MAVSDK to find the vehicle."""


class Vehicle:
    """One autopilot (system 1, component 1) that takes missions and keeps them."""

    def __init__(self, autopilot: int, sdk: Mavsdk) -> None:
        self.autopilot, self.sdk = autopilot, sdk
        self.link = mav.MAVLink(None, srcSystem=1, srcComponent=1)
        self.link.robust_parsing = True
        self.inbox: queue.Queue[bytes] = queue.Queue()
        self.expected = 0
        self.received: dict[int, Any] = {}
        self.missions: list[list[Any]] = []
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)

    def receive(self, data: bytes) -> None:
        """MAVSDK's bytes for the vehicle (called from MAVSDK's thread)."""
        self.inbox.put(bytes(data))

    def _send(self, msg: Any) -> None:
        self.sdk.pass_received_raw_bytes(bytes(msg.pack(self.link)))

    def _run(self) -> None:
        last = 0.0
        while not self.stop.is_set():
            if time.monotonic() - last > HEARTBEAT_PERIOD:
                self._send(mav.MAVLink_heartbeat_message(
                    mav.MAV_TYPE_QUADROTOR, self.autopilot, 0, 0, mav.MAV_STATE_STANDBY, 3))
                last = time.monotonic()
            try:
                data = self.inbox.get(timeout=0.05)
            except queue.Empty:
                continue
            for msg in self.link.parse_buffer(data) or []:
                self._answer(msg)

    def _answer(self, msg: Any) -> None:
        kind = msg.get_type()
        to = (msg.get_srcSystem(), msg.get_srcComponent())
        if kind == "MISSION_COUNT" and msg.mission_type == mav.MAV_MISSION_TYPE_MISSION:
            self.expected, self.received = msg.count, {}
            self._send(mav.MAVLink_mission_request_int_message(*to, 0, msg.mission_type))
        elif kind == "MISSION_ITEM_INT" and msg.seq == len(self.received):
            self.received[msg.seq] = msg
            if len(self.received) < self.expected:
                self._send(mav.MAVLink_mission_request_int_message(*to, msg.seq + 1,
                                                                   msg.mission_type))
            else:
                self.missions.append([self.received[k] for k in range(self.expected)])
                self._send(mav.MAVLink_mission_ack_message(*to, mav.MAV_MISSION_ACCEPTED,
                                                           msg.mission_type))


@contextmanager
def connected(autopilot: int) -> Iterator[tuple[Vehicle, MissionRaw]]:
    """A vehicle of ``autopilot`` (MAV_AUTOPILOT_PX4 or _ARDUPILOTMEGA) and MAVSDK's raw
    mission plugin for it, joined in process."""
    sdk = Mavsdk(Configuration.create_with_component_type(ComponentType.GROUND_STATION))
    vehicle = Vehicle(autopilot, sdk)
    sdk.add_any_connection("raw://")
    sdk.subscribe_raw_bytes_to_be_sent(vehicle.receive)
    vehicle.thread.start()
    try:
        system = sdk.first_autopilot(TIMEOUT)
        assert system is not None, "MAVSDK found no vehicle"
        yield vehicle, MissionRaw(system)
    finally:
        vehicle.stop.set()
        vehicle.thread.join()
        sdk.destroy()


def upload(path: Path, autopilot: int, *, importer: str = "qgroundcontrol") -> list[Any]:
    """The items a vehicle of ``autopilot`` receives when MAVSDK imports the file ``path``
    with its QGroundControl (``.plan``) or Mission Planner (``.waypoints``) importer and
    uploads its mission."""
    with connected(autopilot) as (vehicle, mission):
        imported = getattr(mission, f"import_{importer}_mission")(str(path))
        mission.upload_mission(imported.mission_items)
        assert len(vehicle.missions) == 1, "the vehicle did not take the whole mission"
        return vehicle.missions[0]
