# Every device protocol, one registration each (the function: cmake/ptz_protocol.cmake). Adding a protocol is adding
# its block here; doc/contributing.md lists the files it brings.

ptz_protocol(pantilt
  CORE src/core/pantilt/pantilt_codec.cpp src/core/pantilt/pantilt_params.cpp src/core/pantilt/pantilt_params_json.cpp
    src/core/pantilt/pantilt_protocol.cpp
  PLUGIN src/plugins/pantilt_backend_plugin.cpp
  EMULATOR src/emulators/pantilt_emulator.cpp src/emulators/pantilt_emulator_classify.cpp src/emulators/sim_pantilt.cpp
  PROGRAM pantilt_emulator src/emulators/programs/pantilt_emulator_main.cpp
  HARNESS pantiltHarnesses test/harness/pantilt_harness.cpp
  TESTS test/core/test_pantilt_codec.cpp test/core/test_pantilt_foreign_frames.cpp test/core/test_pantilt_formats.cpp
    test/core/test_pantilt_params.cpp test/core/test_pantilt_protocol.cpp test/core/contract/pantilt_fixtures.cpp
  FUZZ pantilt src/core/pantilt/pantilt_codec.cpp src/core/pantilt/pantilt_params.cpp
    src/core/pantilt/pantilt_params_json.cpp
  ROSTESTS test/ros/pantilt_udp_node.test test/ros/serial_pantilt_node.test test/ros/state_rate_flood.test
    test/ros/nodelet_pantilt_udp.test
)

ptz_protocol(flir
  CORE src/core/flir/flir_codec.cpp src/core/flir/flir_protocol.cpp
  PLUGIN src/plugins/flir_backend_plugin.cpp
  EMULATOR src/emulators/flir_ptu_emulator.cpp src/emulators/flir_ptu_emulator_answers.cpp
    src/emulators/flir_ptu_emulator_classify.cpp
  PROGRAM flir_ptu_emulator src/emulators/programs/flir_ptu_emulator_main.cpp
  HARNESS flirHarnesses test/harness/flir_harness.cpp
  TESTS test/core/test_flir_codec.cpp test/core/test_flir_emulator.cpp test/core/test_flir_protocol.cpp
    test/core/contract/flir_fixtures.cpp
  FUZZ flir_reply src/core/flir/flir_codec.cpp
  ROSTESTS test/ros/serial_flir_node.test
)

ptz_protocol(pelco_d
  CORE src/core/pelco_d/pelco_d_codec.cpp src/core/pelco_d/pelco_d_protocol.cpp src/core/pelco_d/set_position_check.cpp
    src/core/pelco_d/pelco_d_protocol_lens.cpp
  PLUGIN src/plugins/pelco_d_backend_plugin.cpp
  EMULATOR src/emulators/pelco_d_emulator.cpp src/emulators/pelco_d_emulator_classify.cpp
  PROGRAM pelco_d_emulator src/emulators/programs/pelco_d_emulator_main.cpp
  HARNESS pelcoDHarnesses test/harness/pelco_d_harness.cpp
  TESTS test/core/test_pelco_d_codec.cpp test/core/test_pelco_d_protocol.cpp test/core/test_pelco_d_set_position.cpp
    test/core/test_pelco_d_lens.cpp
    test/core/contract/pelco_d_fixtures.cpp
  FUZZ pelco_d src/core/pelco_d/pelco_d_codec.cpp
  ROSTESTS test/ros/serial_pelco_node.test test/ros/pelco_no_set_position_node.test
)

ptz_protocol(visca
  CORE src/core/visca/visca_codec.cpp src/core/visca/visca_model.cpp src/core/visca/visca_presets.cpp
    src/core/visca/visca_lens.cpp src/core/visca/visca_protocol.cpp src/core/visca/visca_protocol_lens.cpp
    src/core/visca/visca_settings.cpp
    src/core/visca/visca_replies.cpp
  PLUGIN src/plugins/visca_backend_plugin.cpp
  EMULATOR src/emulators/visca_emulator.cpp src/emulators/visca_emulator_answers.cpp
    src/emulators/visca_emulator_classify.cpp src/emulators/visca_emulator_lens.cpp
  PROGRAM visca_emulator src/emulators/programs/visca_emulator_main.cpp
  HARNESS viscaHarnesses test/harness/visca_harness.cpp
  TESTS test/core/test_visca_codec.cpp test/core/test_visca_dialects.cpp test/core/test_visca_lens.cpp
    test/core/test_visca_protocol.cpp
    test/core/contract/visca_fixtures.cpp
  FUZZ visca_reply src/core/visca/visca_codec.cpp
  ROSTESTS test/ros/serial_visca_node.test test/ros/visca_ip_node.test test/ros/visca_sony_reply_port.test
)

ptz_protocol(digiview
  CORE src/core/digiview/digiview_codec.cpp src/core/digiview/digiview_formats.cpp
    src/core/digiview/digiview_payloads.cpp src/core/digiview/digiview_protocol.cpp
    src/core/digiview/digiview_aiming.cpp
  PLUGIN src/plugins/digiview_backend_plugin.cpp
  EMULATOR src/emulators/digiview_emulator.cpp src/emulators/digiview_emulator_answers.cpp
    src/emulators/digiview_emulator_classify.cpp
  PROGRAM digiview_emulator src/emulators/programs/digiview_emulator_main.cpp
  HARNESS digiviewHarnesses test/harness/digiview_harness.cpp
  TESTS test/core/test_digiview_emulator.cpp test/core/test_digiview_goldens.cpp
    test/core/test_digiview_goldens_v1_2.cpp test/core/test_digiview_messages.cpp test/core/test_digiview_protocol.cpp
    test/core/test_digiview_halt.cpp test/core/contract/digiview_fixtures.cpp
  FUZZ digiview src/core/digiview/digiview_codec.cpp src/core/digiview/digiview_formats.cpp
    src/core/digiview/digiview_payloads.cpp
  ROSTESTS test/ros/digiview_node.test test/ros/digiview_node_v1_0.test test/ros/digiview_node_v1_1.test
    test/ros/digiview_node_v1_2.test
)

ptz_protocol(mavlink_gimbal
  CORE src/core/mavlink/mavlink_codec.cpp src/core/mavlink/mavlink_gimbal_protocol.cpp
    src/core/mavlink/mavlink_gimbal_replies.cpp src/core/mavlink/mavlink_gimbal_discovery.cpp
    src/core/mavlink/mavlink_gimbal_attitude.cpp src/core/mavlink/mavlink_messages.cpp
    src/core/mavlink/mavlink_quaternion.cpp
  PLUGIN src/plugins/mavlink_gimbal_backend_plugin.cpp
  EMULATOR src/emulators/mavlink_gimbal_emulator.cpp src/emulators/mavlink_gimbal_emulator_commands.cpp
    src/emulators/mavlink_gimbal_emulator_reports.cpp src/emulators/mavlink_gimbal_emulator_classify.cpp
  PROGRAM mavlink_gimbal_emulator src/emulators/programs/mavlink_gimbal_emulator_main.cpp
  HARNESS mavlinkGimbalHarnesses test/harness/mavlink_gimbal_harness.cpp
  TESTS test/core/test_mavlink_codec.cpp test/core/test_mavlink_messages.cpp test/core/test_mavlink_gimbal_goldens.cpp
    test/core/test_mavlink_gimbal_protocol.cpp test/core/test_mavlink_several_gimbals.cpp
    test/core/test_mavlink_gimbal_emulator.cpp test/core/test_mavlink_gimbal_field.cpp
    test/core/contract/mavlink_gimbal_fixtures.cpp
  FUZZ mavlink src/core/mavlink/mavlink_codec.cpp src/core/mavlink/mavlink_messages.cpp
    src/core/mavlink/mavlink_quaternion.cpp
  ROSTESTS test/ros/mavlink_gimbal_node.test
)
# Like mavlink_gimbal_emulator.cpp (CMakeLists.txt), their file-wide `using namespace` stays out of the unity batches.
set_source_files_properties(src/emulators/mavlink_gimbal_emulator_commands.cpp
  src/emulators/mavlink_gimbal_emulator_reports.cpp PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)

ptz_protocol(axis
  CORE src/core/axis/axis_protocol.cpp src/core/axis/axis_zoom_setup.cpp src/core/axis/axis_control_queue.cpp
    src/core/axis/vapix_codec.cpp src/core/axis/vapix_queue.cpp src/core/axis/vapix_zoom.cpp
    src/core/axis/axis_protocol_lens.cpp src/core/axis/vapix_lens.cpp
  PLUGIN src/plugins/axis_backend_plugin.cpp
  EMULATOR src/emulators/axis_camera_emulator.cpp src/emulators/axis_camera_emulator_queue.cpp
    src/emulators/axis_camera_emulator_picture.cpp src/emulators/axis_camera_classify.cpp
    src/emulators/axis_camera_emulator_lens.cpp
  PROGRAM axis_camera_emulator src/emulators/programs/axis_camera_emulator_main.cpp
  HARNESS axisHarnesses test/harness/axis_harness.cpp
  TESTS test/core/test_axis_protocol.cpp test/core/test_axis_zoom.cpp test/core/test_axis_emulator.cpp
    test/core/test_axis_control_queue.cpp test/core/test_vapix_codec.cpp test/core/test_axis_view_aim.cpp
    test/core/test_axis_lens.cpp test/core/contract/axis_fixtures.cpp
  FUZZ vapix_reply src/core/axis/vapix_codec.cpp src/core/axis/vapix_queue.cpp src/core/axis/vapix_zoom.cpp
    src/core/types.cpp
  ROSTESTS test/ros/axis_node.test test/ros/axis_field_node.test test/ros/axis_pixel_aim.test
)

ptz_protocol(onvif
  CORE src/core/onvif/onvif_bring_up.cpp src/core/onvif/onvif_codec.cpp src/core/onvif/onvif_commands.cpp
    src/core/onvif/onvif_motion_check.cpp src/core/onvif/onvif_protocol.cpp src/core/onvif/onvif_ws_security.cpp
    src/core/onvif/onvif_xml.cpp src/core/onvif/onvif_requests.cpp src/core/onvif/onvif_view_aim.cpp
    src/core/onvif/onvif_imaging.cpp src/core/onvif/onvif_lens.cpp
  PLUGIN src/plugins/onvif_backend_plugin.cpp
  EMULATOR src/emulators/onvif_camera_emulator.cpp src/emulators/onvif_camera_emulator_ptz.cpp
    src/emulators/onvif_camera_emulator_modes.cpp src/emulators/onvif_camera_emulator_moves.cpp
    src/emulators/onvif_camera_classify.cpp src/emulators/onvif_camera_emulator_imaging.cpp
  PROGRAM onvif_camera_emulator src/emulators/programs/onvif_camera_emulator_main.cpp
  HARNESS onvifHarnesses test/harness/onvif_harness.cpp
  TESTS test/core/test_onvif_cheap_cameras.cpp test/core/test_onvif_codec.cpp test/core/test_onvif_requests.cpp
    test/core/test_onvif_emulator.cpp test/core/test_onvif_emulator_modes.cpp test/core/test_onvif_motion_check.cpp
    test/core/test_onvif_protocol.cpp test/core/test_onvif_field_modes.cpp test/core/test_onvif_view_aim.cpp
    test/core/test_onvif_move_speed.cpp test/core/test_onvif_lens.cpp
    test/core/contract/onvif_fixtures.cpp
  FUZZ soap_reply src/core/onvif/onvif_codec.cpp src/core/onvif/onvif_requests.cpp src/core/onvif/onvif_ws_security.cpp
    src/core/onvif/onvif_xml.cpp src/core/onvif/onvif_imaging.cpp src/core/http/crypto.cpp src/core/types.cpp
  FUZZ_LIBS tinyxml2::tinyxml2 OpenSSL::Crypto
  ROSTESTS test/ros/onvif_node.test test/ros/onvif_field_node.test test/ros/onvif_continuous_node.test
    test/ros/onvif_no_position_node.test test/ros/onvif_cheap_cameras_node.test
)
