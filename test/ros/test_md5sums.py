#!/usr/bin/env python3
"""rostest: the actions and the state message keep the md5sums of the ptz_action_server_msgs definitions that
existing clients were built against (Clearpath's package; the definitions, field for field, are those of the
interface contract). Each md5sum is computed here by genmsg from that text and compared with the one this package
generated, for the goal, result and feedback of each action (the action's other messages are built from them and
actionlib's own) and for PtzState. A field added, renamed, retyped or reordered in action/ or msg/ fails it.
"""
import unittest

import genmsg.gentools
import genmsg.msg_loader
import rostest

from ptz_action_server import msg

# The contract's definitions (Ptz.action, PtzRelTo.action, PtzFrame.action, PtzState.msg).
ACTIONS = {
    'Ptz': ('float32 pan\nfloat32 tilt\nfloat32 zoom\n', 'bool success\n',
            'float32 pan_remaining\nfloat32 tilt_remaining\nfloat32 zoom_remaining\n'),
    'PtzRelTo': ('float32 pan\nfloat32 tilt\nfloat32 zoom\nstring frame_id\n', 'bool success\n',
                 'float32 pan_remaining\nfloat32 tilt_remaining\nfloat32 zoom_remaining\n'),
    'PtzFrame': ('string frame_id\nfloat32 zoom\n', 'bool success\n',
                 'float32 pan_remaining\nfloat32 tilt_remaining\nfloat32 zoom_remaining\n'),
}
PTZ_STATE = 'int8 MODE_IDLE=0\nint8 MODE_POSITION=1\nint8 MODE_VELOCITY=2\nint8 mode\nfloat32 pan\nfloat32 tilt\n' \
    'float32 zoom\n'


def contract_md5(name, text):
    context = genmsg.msg_loader.MsgContext.create_default()
    spec = genmsg.msg_loader.load_msg_from_string(context, text, 'ptz_action_server_msgs/' + name)
    return genmsg.gentools.compute_md5(context, spec)


class Md5sumTest(unittest.TestCase):

    def test_the_actions_parts_keep_the_contracts_md5sums(self):
        for action, texts in ACTIONS.items():
            for part, text in zip(('Goal', 'Result', 'Feedback'), texts):
                generated = getattr(msg, action + part)._md5sum
                self.assertEqual(generated, contract_md5(action + part, text), '%s%s changed' % (action, part))

    def test_ptz_state_keeps_the_contracts_md5sum(self):
        self.assertEqual(msg.PtzState._md5sum, contract_md5('PtzState', PTZ_STATE))

    def test_a_changed_definition_would_be_seen(self):
        # The comparison can fail: the same goal with its fields in another order has another md5sum.
        self.assertNotEqual(msg.PtzGoal._md5sum, contract_md5('PtzGoal', 'float32 tilt\nfloat32 pan\nfloat32 zoom\n'))


if __name__ == '__main__':
    rostest.rosrun('ptz_action_server', 'md5sums', Md5sumTest)
