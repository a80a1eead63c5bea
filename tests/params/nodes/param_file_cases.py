"""The parameter-file cases the probe runs: files (written as {0}, {1}... in the arguments), the --ros-args given to
rclpy.init, the node's name, namespace and keyword arguments, and the parameters it declares or gets."""

PF = ["--ros-args", "--params-file", "{0}"]
PF2 = ["--ros-args", "--params-file", "{0}", "--params-file", "{1}"]

SCALARS = """/**:
  ros__parameters:
    b_yes: yes
    b_No: No
    b_on: on
    b_off: OFF
    b_y: y
    b_True: True
    b_tRUE: tRUE
    i_plain: 42
    i_plus: +5
    i_neg: -3
    i_octal: 010
    i_hex: 0x1F
    i_under: 1_000
    i_0o: 0o10
    i_big: 99999999999999999999
    d_plain: 1.5
    d_exp: 1e3
    d_EXP: 1E-2
    d_dot: .5
    d_trail: 5.
    d_nan: .nan
    d_NaN: nan
    d_inf: .inf
    d_minf: -.Inf
    d_Infinity: Infinity
    d_hexfloat: 0x1p3
    s_plain: hello world
    s_dq: "5"
    s_sq: '1.5'
    s_tag: !!str 7
    s_true_q: "true"
    s_empty_q: ""
    s_colon: "a: b"
    s_tilde_q: "~"
    s_version: 1.2.3
    s_time: 12:30
    s_int_tag: !!int 7
    s_float_tag: !!float 7
    d_huge: 1e999
    d_tiny: 1e-400
    d_subnormal: 1e-310
    d_leading_zero: 08
    s_0x: 0x
    i_min: -9223372036854775808
    d_over_int: 9223372036854775808
    s_block: |
      12
    s_folded: >-
      3.5
"""

CASES = [
    # -- which node a key names --------------------------------------------------------------------------------------
    {"id": "key_fqn", "files": ["/talker:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "key_bare", "files": ["talker:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "key_bare_node_in_ns", "files": ["talker:\n  ros__parameters:\n    a: 1\n"], "args": PF,
     "namespace": "/ns"},
    {"id": "key_ns_node", "files": ["/ns/talker:\n  ros__parameters:\n    a: 1\n"], "args": PF, "namespace": "/ns"},
    {"id": "key_ns_node_no_slash", "files": ["ns/talker:\n  ros__parameters:\n    a: 1\n"], "args": PF,
     "namespace": "/ns"},
    {"id": "key_nested_ns", "files": ["/ns:\n  talker:\n    ros__parameters:\n      a: 1\n"], "args": PF,
     "namespace": "/ns"},
    {"id": "key_other_node", "files": ["/listener:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "key_all", "files": ["/**:\n  ros__parameters:\n    a: 1\n"], "args": PF, "namespace": "/a/b"},
    {"id": "key_all_node", "files": ["/**/talker:\n  ros__parameters:\n    a: 1\n"], "args": PF,
     "namespace": "/a/b"},
    {"id": "key_all_node_root", "files": ["/**/talker:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "key_ns_star", "files": ["ns/*:\n  ros__parameters:\n    a: 1\n"], "args": PF, "namespace": "/ns"},
    {"id": "key_ns_star_deeper", "files": ["/ns/*:\n  ros__parameters:\n    a: 1\n"], "args": PF,
     "namespace": "/ns/sub"},
    {"id": "key_ns_all_deeper", "files": ["/ns/**:\n  ros__parameters:\n    a: 1\n"], "args": PF,
     "namespace": "/ns/sub"},
    {"id": "key_star_root", "files": ["/*:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "key_star_in_ns", "files": ["/*:\n  ros__parameters:\n    a: 1\n"], "args": PF, "namespace": "/ns"},
    {"id": "key_star_ns_node", "files": ["/*/talker:\n  ros__parameters:\n    a: 1\n"], "args": PF,
     "namespace": "/ns"},
    {"id": "key_partial_star", "files": ["/tal*:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "key_remapped_node", "files": ["/renamed:\n  ros__parameters:\n    a: 1\n"],
     "args": [*PF, "-r", "__node:=renamed"]},
    # -- values ------------------------------------------------------------------------------------------------------
    {"id": "scalars", "files": [SCALARS], "args": PF},
    {"id": "arrays", "files": ["/**:\n  ros__parameters:\n    ints: [1, 2, 3]\n    doubles: [1.5, 2.0]\n"
                               "    bools: [true, no]\n    strings: [a, 'b', \"3\"]\n"
                               "    block:\n      - 1.0\n      - 2.5\n    one: [7]\n"], "args": PF},
    {"id": "array_mixed_int_double", "files": ["/**:\n  ros__parameters:\n    a: [1, 2.5]\n"], "args": PF},
    {"id": "array_mixed_int_string", "files": ["/**:\n  ros__parameters:\n    a: [1, x]\n"], "args": PF},
    {"id": "array_mixed_string_bool", "files": ["/**:\n  ros__parameters:\n    a: [x, true]\n"], "args": PF},
    {"id": "array_empty", "files": ["/**:\n  ros__parameters:\n    a: []\n    b: 1\n"], "args": PF},
    {"id": "array_nested", "files": ["/**:\n  ros__parameters:\n    a: [[1, 2], [3]]\n"], "args": PF},
    {"id": "value_null", "files": ["/**:\n  ros__parameters:\n    a: ~\n"], "args": PF},
    {"id": "value_missing", "files": ["/**:\n  ros__parameters:\n    a:\n    b: 1\n"], "args": PF},
    {"id": "nested_keys_ok", "files": ["/**:\n  ros__parameters:\n    robot:\n      speed: 0.2\n      limits:\n"
                                       "        max: 1.0\n        names: [left, right]\n    after: 3\n"
                                       "    dotted.key: 4\n    dotted.map:\n      x: 1\n      y_: 2\n"], "args": PF},
    {"id": "empty_map_value", "files": ["/**:\n  ros__parameters:\n    a: {}\n    b: 1\n"], "args": PF},
    {"id": "list_of_maps", "files": ["/**:\n  ros__parameters:\n    a:\n      - x: 1\n      - x: 2\n"],
     "args": PF},
    {"id": "duplicate_key_types", "files": ["/**:\n  ros__parameters:\n    a: x\n    a: 5\n    b: 5\n    b: x\n"
                                            "    c: [1]\n    c: 2.5\n    d: 1\n    d: 2\n"], "args": PF},
    {"id": "two_files_type_change", "files": ["/**:\n  ros__parameters:\n    a: 5\n    b: [1, 2]\n    c: x\n",
                                              "/**:\n  ros__parameters:\n    a: x\n    b: [3]\n    c: 1.5\n"],
     "args": PF2},
    {"id": "two_nodes_one_file", "files": ["/talker:\n  ros__parameters:\n    a: 1\n/listener:\n  ros__parameters:\n"
                                           "    a: 2\n/ns:\n  talker:\n    ros__parameters:\n      b: 3\n"
                                           "  other:\n    ros__parameters:\n      b: 4\n"], "args": PF,
     "namespace": "/ns"},
    {"id": "empty_key", "files": ["/**:\n  ros__parameters:\n    \"\": 1\n"], "args": PF},
    {"id": "node_key_empty_name", "files": ["/ns/:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "sequence_under_node", "files": ["talker: [1, 2]\n"], "args": PF},
    {"id": "nested_keys", "files": ["/**:\n  ros__parameters:\n    robot:\n      speed: 0.2\n      limits:\n"
                                    "        max: 1.0\n        names: [x, y]\n    after: 3\n"
                                    "    dotted.key: 4\n"], "args": PF},
    {"id": "flow_map", "files": ["/**:\n  ros__parameters:\n    pid: {p: 1.0, i: 0, d: 0.1}\n"], "args": PF},
    {"id": "alias", "files": ["/**:\n  ros__parameters:\n    a: &x 1\n    b: *x\n"], "args": PF},
    {"id": "two_documents", "files": ["/**:\n  ros__parameters:\n    a: 1\n---\n/talker:\n  ros__parameters:\n"
                                      "    b: 2\n"], "args": PF},
    {"id": "tags", "files": ["/**:\n  ros__parameters:\n    bin: !!binary aGVsbG8=\n    b: !!bool yes\n"
                             "    n: !!null ~\n    s: !!str [1]\n    local: !mytag 3\n"], "args": PF},
    {"id": "unicode_and_crlf", "files": ["/**:\r\n  ros__parameters:\r\n    name: caf\u00e9\r\n    x: 1.5\r\n"],
     "args": PF},
    {"id": "comments_and_block_styles", "files": ["# robot settings\n/**:  # every node\n  ros__parameters:\n"
                                                  "    text: |\n      two\n      lines\n    folded: >\n      a\n      b\n"
                                                  "    plain: multi\n      word\n"], "args": PF},
    {"id": "file_is_directory", "args": ["--ros-args", "--params-file", "{DIR}"]},
    {"id": "use_sim_time_file", "files": ["/**:\n  ros__parameters:\n    use_sim_time: true\n"], "args": PF},
    # -- errors ------------------------------------------------------------------------------------------------------
    {"id": "file_missing", "args": ["--ros-args", "--params-file", "{DIR}/nowhere.yaml"]},
    {"id": "file_empty", "files": [""], "args": PF},
    {"id": "file_malformed", "files": ["/**:\n  ros__parameters:\n    a: 1\n   b: 2\n"], "args": PF},
    {"id": "file_tab", "files": ["/**:\n\tros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "file_unclosed", "files": ["/**:\n  ros__parameters:\n    a: [1, 2\n"], "args": PF},
    {"id": "no_ros_parameters", "files": ["talker:\n  a: 1\n"], "args": PF},
    {"id": "misspelt_ros_parameters", "files": ["talker:\n  ros_parameters:\n    a: 1\n"], "args": PF},
    {"id": "top_level_value", "files": ["a: 1\n"], "args": PF},
    {"id": "ros_parameters_first", "files": ["ros__parameters:\n  a: 1\n"], "args": PF},
    {"id": "bad_node_name", "files": ["/1talker:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "bad_namespace", "files": ["/ns//talker:\n  ros__parameters:\n    a: 1\n"], "args": PF},
    {"id": "top_level_list", "files": ["- a\n- b\n"], "args": PF},
    {"id": "params_file_no_value", "args": ["--ros-args", "--params-file"]},
    # -- which value wins ------------------------------------------------------------------------------------------
    {"id": "two_files_later_wins", "files": ["/**:\n  ros__parameters:\n    a: 1\n    b: 1\n",
                                             "/**:\n  ros__parameters:\n    a: 2\n"], "args": PF2},
    {"id": "node_then_all_files", "files": ["/talker:\n  ros__parameters:\n    a: 1\n",
                                            "/**:\n  ros__parameters:\n    a: 2\n"], "args": PF2},
    {"id": "all_then_node_files", "files": ["/**:\n  ros__parameters:\n    a: 1\n",
                                            "/talker:\n  ros__parameters:\n    a: 2\n"], "args": PF2},
    {"id": "all_node_all_files", "files": ["/**:\n  ros__parameters:\n    a: 1\n/talker:\n  ros__parameters:\n"
                                           "    a: 2\n", "/**:\n  ros__parameters:\n    a: 3\n"], "args": PF2},
    {"id": "node_all_in_one_file", "files": ["/talker:\n  ros__parameters:\n    a: 2\n/**:\n  ros__parameters:\n"
                                             "    a: 1\n"], "args": PF},
    {"id": "bare_and_fqn_keys", "files": ["talker:\n  ros__parameters:\n    a: 1\n/talker:\n  ros__parameters:\n"
                                          "    a: 2\n"], "args": PF},
    {"id": "p_after_file", "files": ["/**:\n  ros__parameters:\n    a: 1\n    b: 1\n"],
     "args": [*PF, "-p", "a:=5"]},
    {"id": "p_before_file", "files": ["/**:\n  ros__parameters:\n    a: 1\n"],
     "args": ["--ros-args", "-p", "a:=5", "--params-file", "{0}"]},
    {"id": "p_before_node_file", "files": ["/talker:\n  ros__parameters:\n    a: 1\n"],
     "args": ["--ros-args", "-p", "a:=5", "--params-file", "{0}"]},
    {"id": "p_scoped_and_global", "args": ["--ros-args", "-p", "talker:a:=1", "-p", "a:=2", "-p", "b:=3",
                                           "-p", "talker:b:=4"]},
    {"id": "p_scoped_other_node", "args": ["--ros-args", "-p", "listener:a:=1"]},
    {"id": "p_scoped_in_ns", "args": ["--ros-args", "-p", "talker:a:=1"], "namespace": "/ns"},
    {"id": "p_values", "args": ["--ros-args", "-p", "a:=1_000", "-p", "b:=010", "-p", "c:=[1, 2]", "-p", "e:='x'",
                                "-p", "f:=[a, 'b']", "-p", "g:=0o10", "-p", "h:=yes", "-p", "i:=[]", "-p", "j:=~",
                                "-p", "k:=1e3", "-p", "nested.name:=x"]},
    {"id": "p_empty_value", "args": ["--ros-args", "-p", "d:="]},
    # A scenario's node parameters come after the node's own args, in a --ros-args section of their own.
    {"id": "p_later_section_wins", "args": ["--ros-args", "-p", "a:=left", "-p", "b:=0.4", "-r", "x:=y",
                                            "--ros-args", "-p", "a:=right", "-p", "b:=0.5", "-p", 's:="1.0"',
                                            "-p", 't:="on"']},
    {"id": "p_after_non_ros_args", "args": ["_a:=left", "--ros-args", "-p", "a:=x", "--", "plain",
                                            "--ros-args", "-p", "a:=right"]},
    # rcl still takes a ROS 1 style `from:=to` outside --ros-args as a remap rule, with a warning, when it is one.
    {"id": "deprecated_remap_rules", "args": ["_a:=left", "_b:=0.4", "c:=/d/e", "f:=~/g", "h:=i:=j", "k/*:=m",
                                              "rostopic://n:=o", "p:q:=r", "s:=", ":=t", "plain"]},
    {"id": "p_map_value", "args": ["--ros-args", "-p", "d:={x: 1}"]},
    {"id": "p_bad_yaml", "args": ["--ros-args", "-p", "d:=[1, 2"]},
    {"id": "p_then_file_other_type", "files": ["/**:\n  ros__parameters:\n    a: x\n"],
     "args": ["--ros-args", "-p", "a:=5", "--params-file", "{0}"]},
    {"id": "p_mixed_array", "args": ["--ros-args", "-p", "a:=[1, 2.5]"]},
    {"id": "p_rules_accepted", "args": ["--ros-args", "-p", "talker:a.b:=1", "-p", "a/b:=2", "-p", "c:=x:=y",
                                        "-p", "d__e:=1", "-p", "_f_:=2", "-p", "talker:g.h.i:=[]"]},
    {"id": "p_rule_dunder", "args": ["--ros-args", "-p", "__d:=1"]},
    {"id": "p_rule_node_keyword", "args": ["--ros-args", "-p", "__node:=x"]},
    {"id": "p_rule_no_separator", "args": ["--ros-args", "-p", "a"]},
    {"id": "p_rule_fqn_prefix", "args": ["--ros-args", "-p", "/ns/talker:b:=2"]},
    {"id": "p_rule_no_name", "args": ["--ros-args", "-p", ":=1"]},
    {"id": "p_rule_space", "args": ["--ros-args", "-p", "tal ker:a:=1"]},
    {"id": "p_rule_wildcard", "args": ["--ros-args", "-p", "*:a:=1"]},
    {"id": "p_rule_wildcards", "args": ["--ros-args", "-p", "**:a:=1"]},
    {"id": "p_rule_two_colons", "args": ["--ros-args", "-p", "talker:x:y:=1"]},
    {"id": "p_rule_digit", "args": ["--ros-args", "-p", "1a:=2"]},
    {"id": "p_rule_dash", "args": ["--ros-args", "-p", "max-speed:=2"]},
    {"id": "p_rule_trailing", "args": ["--ros-args", "-p"]},
    {"id": "trailing_remap", "args": ["--ros-args", "-r"]},
    {"id": "trailing_log_level", "args": ["--ros-args", "--log-level"]},
    {"id": "trailing_enclave", "args": ["--ros-args", "-e"]},
    {"id": "bad_log_level", "args": ["--ros-args", "--log-level", "loud"]},
    {"id": "cli_args_file_over_global", "files": ["/**:\n  ros__parameters:\n    a: 1\n    b: 1\n",
                                                  "/**:\n  ros__parameters:\n    a: 2\n"],
     "args": PF, "cli_args": ["--params-file", "{1}"]},
    {"id": "cli_args_no_global", "files": ["/**:\n  ros__parameters:\n    a: 1\n    b: 1\n",
                                           "/**:\n  ros__parameters:\n    a: 2\n"],
     "args": PF, "cli_args": ["--params-file", "{1}"], "kwargs": {"use_global_arguments": False}},
    {"id": "cli_args_missing_file", "args": [], "cli_args": ["--params-file", "{DIR}/nowhere.yaml"]},
    {"id": "cli_args_ros_args_file", "files": ["/**:\n  ros__parameters:\n    a: 1\n    b: 1\n",
                                               "/**:\n  ros__parameters:\n    a: 2\n"],
     "args": PF, "cli_args": ["--ros-args", "--params-file", "{1}"]},
    {"id": "cli_args_ros_args_p", "files": ["/talker:\n  ros__parameters:\n    a: 1\n"],
     "args": PF, "cli_args": ["--ros-args", "-p", "a:=3"]},
    {"id": "cli_args_ros_args_missing_file", "args": [],
     "cli_args": ["--ros-args", "--params-file", "{DIR}/nowhere.yaml"]},
    {"id": "overrides_kwarg_over_file", "files": ["/**:\n  ros__parameters:\n    a: 1\n    b: 1\n"], "args": PF,
     "kwargs": {"parameter_overrides": [["a", 9], ["c", "x"]]}},
    # -- declaring ---------------------------------------------------------------------------------------------------
    {"id": "declare_with_file", "files": ["/**:\n  ros__parameters:\n    speed: 0.5\n    name: bob\n    n: 3\n"],
     "args": PF, "declare": [["speed", 0.1], ["name", "x"], ["other", 7], ["n", 1.0]]},
    {"id": "declare_type_mismatch", "files": ["/**:\n  ros__parameters:\n    speed: fast\n"], "args": PF,
     "declare": [["speed", 0.1]]},
    {"id": "declare_int_for_double", "files": ["/**:\n  ros__parameters:\n    speed: 1\n"], "args": PF,
     "declare": [["speed", 0.1]]},
    {"id": "declare_forms", "files": ["/**:\n  ros__parameters:\n    typed: 3\n    bare: x\n    ignored: 5\n"
                                      "    dyn: text\n    ro: 2.5\n    robot:\n      speed: 0.7\n      name: r1\n"
                                      "    unset: []\n"], "args": PF,
     "calls": ["node.declare_parameter('typed', Parameter.Type.INTEGER)",
               "node.declare_parameter('ignored', 1, ignore_override=True)",
               "node.declare_parameter('dyn', 4, ParameterDescriptor(dynamic_typing=True))",
               "node.declare_parameter('ro', 1.0, ParameterDescriptor(read_only=True))",
               "node.declare_parameters('robot', [('speed', 0.1), ('name', 'none'), ('extra', True)])",
               "node.get_parameters_by_prefix('robot')",
               "node.declare_parameter('unset', 'default')",
               "node.declare_parameter('typed_missing', Parameter.Type.DOUBLE)",
               "node.get_parameter_or('nowhere', Parameter('nowhere', value=9))",
               "node.has_parameter('robot.speed')",
               "node.set_parameters([Parameter('ro', value=3.0)])[0].successful"]},
    {"id": "declare_type_from_file_unset", "files": ["/**:\n  ros__parameters:\n    a: []\n"], "args": PF,
     "calls": ["node.declare_parameter('a', Parameter.Type.INTEGER_ARRAY)",
               "node.get_parameter('a')"]},
    {"id": "undeclared_get", "files": ["/**:\n  ros__parameters:\n    a: 1\n"], "args": PF, "get": ["a"]},
    {"id": "allow_undeclared", "files": ["/**:\n  ros__parameters:\n    a: 1\n"], "args": PF, "get": ["a", "zz"],
     "kwargs": {"allow_undeclared_parameters": True}},
    {"id": "auto_declare", "files": ["/**:\n  ros__parameters:\n    a: 1\n    nested:\n      b: [1.0, 2.0]\n"],
     "args": PF, "get": ["a", "nested.b"],
     "kwargs": {"automatically_declare_parameters_from_overrides": True}},
    {"id": "auto_declare_then_declare", "files": ["/**:\n  ros__parameters:\n    a: 1\n"], "args": PF,
     "declare": [["a", 2]], "kwargs": {"automatically_declare_parameters_from_overrides": True}},
]
