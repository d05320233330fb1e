<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/ros2-build.xsl - CMakeLists.txt (ament_cmake) and
  package.xml (format 3) of the ROS 2 package.

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 2).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  model-dir-from-output (ros-common/ros-text.xsl).  Errors: none.

  One shared library <pkg>_components with every node class (+ the
  user's <Class>Impl.cpp of a node without a realizing class, and the
  lifecycle class of a node with a managed instance), registered with
  rclcpp_components_register_nodes; one executable per node, and
  lifecycle_manager when a node is managed; the
  atomic-code library as in ROS 1; generated messages with
  rosidl_generate_interfaces. Headers install under include/<pkg>/ (the
  data types' include/<Type>.hpp too), exported as the include folder.
  The option ROBOMDA_WARNINGS (on) adds -Wall -Wextra -Wpedantic; colcon
  test runs ament_lint_common (fp:ros2-tests), package.xml test-depends on
  it.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:ros2-deps" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="sort(distinct-values(('rclcpp', 'rclcpp_components',
        if ($package/r:node[@lifecycle-type-name]) then ('rclcpp_lifecycle', 'lifecycle_msgs') else (),
        if ($package/r:coordinator) then 'std_msgs' else (),
        ($package/r:node/r:port/r:message/@msg, $package/r:node/r:service/@srv, $package/r:node/r:service-client/@srv)[contains(., '/')] ! substring-before(., '/'),
        (: what the generated messages use :)
        fp:message-dependencies($package))))"/>
  </xsl:function>

  <xsl:function name="fp:ros2-cmakelists" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:variable name="deps" as="xs:string*" select="fp:ros2-deps($package)"/>
    <xsl:variable name="lib" as="xs:string" select="'${PROJECT_NAME}_components'"/>
    <!-- messages or services of its own to generate -->
    <xsl:variable name="msgs" as="xs:boolean" select="exists($package/r:types/*[@message] | $package/r:service-type)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $fp:build-xsl, concat('model ''', $package/@model-name, ''''), false()),
        'cmake_minimum_required(VERSION 3.8)',
        concat('project(', $package/@name, ')'),
        '',
        'set(CMAKE_CXX_STANDARD 17)',
        'set(CMAKE_CXX_STANDARD_REQUIRED ON)',
        fp:cmake-warnings(),
        '',
        'find_package(ament_cmake REQUIRED)',
        $deps ! (concat('find_package(', ., ' REQUIRED)')),
        if ($msgs) then (
          'find_package(rosidl_default_generators REQUIRED)',
          concat('rosidl_generate_interfaces(${PROJECT_NAME} ', string-join(($package/r:types/*/@message ! ('&quot;msg/' || . || '.msg&quot;'),
                                                                   $package/r:service-type/@name ! ('&quot;srv/' || . || '.srv&quot;')), ' '),
                 string-join(('', 'DEPENDENCIES'[exists(fp:message-dependencies($package))], fp:message-dependencies($package)), ' '), ')'),
          'rosidl_get_typesupport_target(${PROJECT_NAME}_msgs_cpp ${PROJECT_NAME} &quot;rosidl_typesupport_cpp&quot;)')
        else (),
        $package/r:library ! fp:library-external-project(.),
        '',
        '# every node class, as rclcpp components',
        fp:cmake-call(0, 'add_library(' || $lib || ' SHARED', ($package/r:node ! (concat('src/', @class, '.cpp'), fp:ros-user-sources(.)),
                                                            $package/r:node[@lifecycle-type-name] ! concat('src/lifecycle/', @class, '.cpp'))),
        concat('target_include_directories(', $lib, ' PUBLIC'),
        '  $&lt;BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include&gt;',
        '  $&lt;INSTALL_INTERFACE:include/${PROJECT_NAME}&gt;)',
        fp:cmake-call(0, 'ament_target_dependencies(' || $lib, $deps),
        if ($msgs) then concat('target_link_libraries(', $lib, ' ${${PROJECT_NAME}_msgs_cpp})') else (),
        fp:library-depends($package/r:library, $lib),
        if ($package/r:library) then concat('target_link_libraries(', $lib, ' ', string-join(fp:library-vars($package/r:library), ' '), ')') else (),
        fp:cmake-call(0, 'rclcpp_components_register_nodes(' || $lib,
                      ($package/r:node/@type-name, $package/r:node/@lifecycle-type-name) ! concat('&quot;', ., '&quot;')),
        for $n in $package/r:node return (
          '',
          concat('# node of component ', $n/@name),
          concat('add_executable(', $n/@executable, ' src/', $n/@executable, '.cpp)'),
          concat('target_link_libraries(', $n/@executable, ' ', $lib, ')')),
        for $c in $package/r:coordinator return (
          '',
          concat('# the job coordinator of subsystem ', $c/@name),
          concat('add_executable(', $c/@executable, ' src/', $c/@executable, '.cpp)'),
          concat('ament_target_dependencies(', $c/@executable, ' rclcpp lifecycle_msgs std_msgs)')),
        if ($package/r:host[@lifecycle-manager]) then (
          '',
          '# configures, then activates, the managed nodes in the deployment sequence',
          'add_executable(lifecycle_manager src/lifecycle_manager.cpp)',
          'ament_target_dependencies(lifecycle_manager rclcpp lifecycle_msgs)')
        else (),
        '',
        concat('install(TARGETS ', $lib),
        '  ARCHIVE DESTINATION lib',
        '  LIBRARY DESTINATION lib',
        '  RUNTIME DESTINATION bin)',
        fp:cmake-call(0, 'install(TARGETS', ($package/r:node/@executable, $package/r:coordinator/@executable,
                                             $package/r:host[@lifecycle-manager][1] ! 'lifecycle_manager', 'DESTINATION lib/${PROJECT_NAME}')),
        '# headers under include/${PROJECT_NAME}/: in a merged install, two packages'' data types',
        '# of one name (include/${PROJECT_NAME}/Type.hpp) stay apart',
        'install(DIRECTORY include/ DESTINATION include/${PROJECT_NAME})',
        'install(DIRECTORY config launch',
        '  DESTINATION share/${PROJECT_NAME})',
        'ament_export_include_directories(&quot;include/${PROJECT_NAME}&quot;)',
        '',
        fp:ros2-tests($package),
        '',
        'ament_package()'))"/>
  </xsl:function>

  <!-- colcon test: ROS 2's linters (ament_lint_common) and the system's
       launch test (ros2-test.xsl); without a copyright
       notice ament_copyright accepts (f:copyright-checkable: a maintainer,
       a year and a license licenses.xml has), ament_copyright is left out,
       and without any notice cpplint's legal/copyright check too -->
  <xsl:function name="fp:ros2-tests" as="xs:string+">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:variable name="notice" as="xs:boolean" select="normalize-space($maintainer-name) ne ''"/>
    <xsl:sequence select="
        '# colcon test: ROS 2''s linters (ament_lint_common) and the launch test of the system',
        'if(BUILD_TESTING)',
        '  find_package(ament_lint_auto REQUIRED)',
        if (f:copyright-checkable()) then () else (
          '  # no copyright notice ament_copyright recognises: generate with --maintainer and a',
          '  # --license whose notice robomda writes (' || string-join($fp:license-notices/@spdx, ', ') || ')',
          '  list(APPEND AMENT_LINT_AUTO_EXCLUDE ament_cmake_copyright)'),
        if ($notice) then () else (
          '  # no copyright line either: cpplint runs without its legal/copyright check',
          '  list(APPEND AMENT_LINT_AUTO_EXCLUDE ament_cmake_cpplint)'),
        '  ament_lint_auto_find_test_dependencies()',
        if ($notice) then () else '  ament_cpplint(FILTERS &quot;-legal/copyright&quot;)',
        fp:ros2-launch-test-cmake($package),
        'endif()'"/>
  </xsl:function>

  <xsl:function name="fp:ros2-package-xml" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <!-- messages or services of its own to generate -->
    <xsl:variable name="msgs" as="xs:boolean" select="exists($package/r:types/*[@message] | $package/r:service-type)"/>
    <xsl:sequence select="fp:lines((
        fp:ros-package-xml-opening($package),
        f:package-manifest-fields(concat('  &lt;description&gt;Nodes of model ', fp:xml-text($package/@model-name), ' for ROS 2 (rclcpp), generated by robomda.&lt;/description&gt;')),
        '',
        '  &lt;buildtool_depend&gt;ament_cmake&lt;/buildtool_depend&gt;',
        if ($msgs) then '  &lt;buildtool_depend&gt;rosidl_default_generators&lt;/buildtool_depend&gt;' else (),
        fp:ros2-deps($package) ! (concat('  &lt;depend&gt;', ., '&lt;/depend&gt;')),
        if ($msgs) then ('  &lt;exec_depend&gt;rosidl_default_runtime&lt;/exec_depend&gt;',
                         '  &lt;member_of_group&gt;rosidl_interface_packages&lt;/member_of_group&gt;') else (),
        '  &lt;exec_depend&gt;ros2launch&lt;/exec_depend&gt;',
        '',
        '  &lt;test_depend&gt;ament_lint_auto&lt;/test_depend&gt;',
        '  &lt;test_depend&gt;ament_lint_common&lt;/test_depend&gt;',
        ('ament_index_python', 'launch', 'launch_testing', 'launch_testing_ament_cmake', 'lifecycle_msgs', 'python3-pytest',
         'python3-yaml', 'rcl_interfaces', 'rclpy', 'rosidl_runtime_py') ! ('  &lt;test_depend&gt;' || . || '&lt;/test_depend&gt;'),
        '',
        '  &lt;export&gt;',
        '    &lt;build_type&gt;ament_cmake&lt;/build_type&gt;',
        '  &lt;/export&gt;',
        '&lt;/package&gt;'))"/>
  </xsl:function>
</xsl:stylesheet>
