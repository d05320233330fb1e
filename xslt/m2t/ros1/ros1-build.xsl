<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros1/ros1-build.xsl - CMakeLists.txt (catkin) and package.xml
  (format 3) of the ROS 1 package.

  Reads:   r:package of urn:robomda:psm-ros:1 (ros-version 1).
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  model-dir-from-output (ros-common/ros-text.xsl).  Errors: none.

  One executable per node (its class source + its main, + the user's
  <Class>Impl.cpp without a realizing class); the atomic-code
  library is found as in the Orocos target (cache variable <PKG>_<LIB>_DIR
  defaulting to the model-relative artifact path). Generated messages:
  add_message_files / generate_messages with message_generation.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- the packages of the messages and services the nodes use, sorted -->
  <xsl:function name="fp:ros1-deps" as="xs:string*">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:sequence select="sort(distinct-values(('roscpp',
        if ($package/r:coordinator) then ('std_msgs', 'std_srvs') else (),
        ($package/r:node/r:port/r:message/@msg, $package/r:node/r:service/@srv, $package/r:node/r:service-client/@srv)[contains(., '/')] ! substring-before(., '/'),
        (: what the generated messages use :)
        fp:message-dependencies($package))))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-cmakelists" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <xsl:variable name="deps" as="xs:string*" select="fp:ros1-deps($package)"/>
    <!-- messages or services of its own to generate -->
    <xsl:variable name="msgs" as="xs:boolean" select="exists($package/r:types/*[@message] | $package/r:service-type)"/>
    <!-- the libraries every node links, found once (not per node) -->
    <xsl:variable name="libraries" as="element(r:library)*" select="$package/r:library"/>
    <xsl:variable name="library-vars" as="xs:string" select="string-join(fp:library-vars($libraries), ' ')"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $fp:build-xsl, concat('model ''', $package/@model-name, ''''), false()),
        'cmake_minimum_required(VERSION 3.0.2)',
        concat('project(', $package/@name, ')'),
        '',
        'set(CMAKE_CXX_STANDARD 14)',
        'set(CMAKE_CXX_STANDARD_REQUIRED ON)',
        fp:cmake-warnings(),
        '',
        concat('find_package(catkin REQUIRED COMPONENTS ', string-join(($deps, if ($msgs) then 'message_generation' else ()), ' '), ')'),
        if ($msgs) then (
          '',
          $package/r:types[*/@message] ! concat('add_message_files(FILES ', string-join(*/@message ! (. || '.msg'), ' '), ')'),
          $package[r:service-type] ! concat('add_service_files(FILES ', string-join(r:service-type/@name ! (. || '.srv'), ' '), ')'),
          concat('generate_messages(', string-join(('DEPENDENCIES'[exists(fp:message-dependencies($package))], fp:message-dependencies($package)), ' '), ')'))
        else (),
        '',
        'catkin_package(',
        concat('  CATKIN_DEPENDS ', string-join(($deps, if ($msgs) then 'message_runtime' else ()), ' ')),
        ')',
        '',
        'include_directories(include ${catkin_INCLUDE_DIRS})',
        $package/r:library ! fp:library-external-project(.),
        for $n in $package/r:node return (
          '',
          concat('# node of component ', $n/@name, ': executable ', $n/@executable),
          concat('add_executable(${PROJECT_NAME}_', $n/@executable, ' src/', $n/@class, '.cpp src/', $n/@executable, '.cpp',
                 string-join(fp:ros-user-sources($n) ! (' ' || .)), ')'),
          concat('set_target_properties(${PROJECT_NAME}_', $n/@executable, ' PROPERTIES OUTPUT_NAME ', $n/@executable, ')'),
          concat('add_dependencies(${PROJECT_NAME}_', $n/@executable, ' ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})'),
          fp:library-depends($libraries, concat('${PROJECT_NAME}_', $n/@executable)),
          concat('target_link_libraries(${PROJECT_NAME}_', $n/@executable, ' ${catkin_LIBRARIES} ', $library-vars, ')')),
        for $c in $package/r:coordinator return (
          '',
          concat('# the job coordinator of subsystem ', $c/@name),
          concat('add_executable(${PROJECT_NAME}_', $c/@executable, ' src/', $c/@executable, '.cpp)'),
          concat('set_target_properties(${PROJECT_NAME}_', $c/@executable, ' PROPERTIES OUTPUT_NAME ', $c/@executable, ')'),
          concat('add_dependencies(${PROJECT_NAME}_', $c/@executable, ' ${catkin_EXPORTED_TARGETS})'),
          concat('target_link_libraries(${PROJECT_NAME}_', $c/@executable, ' ${catkin_LIBRARIES})')),
        '',
        concat('install(TARGETS ', string-join(sort(($package/r:node/@executable, $package/r:coordinator/@executable)) ! (concat('${PROJECT_NAME}_', .)), ' ')),
        '  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})',
        'install(DIRECTORY include/${PROJECT_NAME}/',
        '  DESTINATION ${CATKIN_PACKAGE_INCLUDE_DESTINATION})',
        'install(DIRECTORY config launch',
        '  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})',
        fp:ros1-test-cmake($package)))"/>
  </xsl:function>

  <xsl:function name="fp:ros1-package-xml" as="xs:string">
    <xsl:param name="package" as="element(r:package)"/>
    <!-- messages or services of its own to generate -->
    <xsl:variable name="msgs" as="xs:boolean" select="exists($package/r:types/*[@message] | $package/r:service-type)"/>
    <xsl:sequence select="fp:lines((
        fp:ros-package-xml-opening($package),
        f:package-manifest-fields(concat('  &lt;description&gt;Nodes of model ', fp:xml-text($package/@model-name), ' for ROS 1 (roscpp), generated by robomda.&lt;/description&gt;')),
        '',
        '  &lt;buildtool_depend&gt;catkin&lt;/buildtool_depend&gt;',
        fp:ros1-deps($package) ! (concat('  &lt;depend&gt;', ., '&lt;/depend&gt;')),
        if ($msgs) then ('  &lt;build_depend&gt;message_generation&lt;/build_depend&gt;',
                         '  &lt;exec_depend&gt;message_runtime&lt;/exec_depend&gt;') else (),
        '  &lt;exec_depend&gt;roslaunch&lt;/exec_depend&gt;',
        ('python3-yaml', 'rosgraph', 'rospy', 'rostest') ! ('  &lt;test_depend&gt;' || . || '&lt;/test_depend&gt;'),
        '&lt;/package&gt;'))"/>
  </xsl:function>
</xsl:stylesheet>
