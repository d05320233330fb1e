<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros-common/ros-user.xsl - the code of a ROS component without a
  realizing class (ROS 1 and ROS 2 alike: plain C++, no ROS in it).

  Reads:   r:node of kind "base" of urn:robomda:psm-ros:1 (N9 of
           xslt/m2m/ros/psm.xsl: its r:realizing-class is the user's class,
           its r:member the parameters' members).
  Writes:  fs:file elements (schemas/fileset/1/fileset.xsd), for main.xsl:
             include/<pkg>/<Class>Base.hpp     generated, every run
             include/<pkg>/<Class>Impl.hpp     the user's (mode user), written once
             src/<Class>Impl.cpp               the user's (mode user), written once
  Params:  none.  Errors: none.
  Uses:    ../common/user-class.xsl (the user files, shared with Orocos),
           ../common/text.xsl; both included by main.xsl.

  <Class>Base declares every hook the node calls, pure virtual: the
  lifecycle (configure, start, update, stop, cleanup), set<Datum>(value) of
  each input port, get<Datum>() of each output port, the operation of each
  service, and the required operations the node implements by calling the
  provider; it holds the members the parameters set. The user's
  <Class>Impl derives from it and overrides the hooks ("override"); the
  node <Class> (the wrapper of ros1-cpp.xsl / ros2-cpp.xsl, unchanged)
  derives from <Class>Impl and calls them. A hook the model no longer has
  is gone from <Class>Base: its override stops the build; a new one leaves
  <Class>Impl abstract: the node does not compile until it is implemented.
  (Warning OUT004 names the changes too.)

    fp:ros-user-files($node)     the three files, () for a wrapper
    fp:ros-user-sources($node)   the user's source files the build compiles
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:variable name="fp:user-xsl" as="xs:string" select="'m2t/ros-common/ros-user.xsl'"/>

  <xsl:function name="fp:ros-user-files" as="element(fs:file)*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:for-each select="$node[@kind eq 'base']">
      <xsl:variable name="pkg" as="xs:string" select="@namespace"/>
      <xsl:variable name="user" as="xs:string" select="r:realizing-class/@name"/>
      <xsl:sequence select="fp:file(concat('include/', $pkg, '/', @generated-class, '.hpp'), 'generated', $fp:user-xsl, fp:ros-base-header(.))"/>
      <xsl:sequence select="fp:user-class-file(concat('include/', $pkg, '/', $user, '.hpp'), $fp:user-xsl, ., fp:ros-user-signature(.),
          fp:user-class-header($fp:user-xsl, ., $pkg, $user, @generated-class, ('protected:', fp:hook-declarations(fp:ros-hooks(.), '  ', ' override;')), '.hpp', ()))"/>
      <xsl:sequence select="fp:user-class-file(concat('src/', $user, '.cpp'), $fp:user-xsl, ., fp:ros-user-signature(.),
          fp:user-class-source($fp:user-xsl, ., $pkg, $user, fp:ros-user-definitions(.), '.hpp', ()))"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="fp:ros-user-sources" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="$node[@kind eq 'base'] ! concat('src/', r:realizing-class/@name, '.cpp')"/>
  </xsl:function>

  <!-- what <Class>Base requires of the user's class (warning OUT004 when
       it changes) -->
  <xsl:function name="fp:ros-user-signature" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:sequence select="fp:ros-hooks($node) ! ('hook ' || ?decl), $node/r:member ! concat('member ', @cpp-type, ' ', @name)"/>
  </xsl:function>

  <!-- the hooks of $node, in order: each a map of its declaration (decl:
       "bool configure()"), the comment on its group (group), the name it
       has in the user's source (head: "bool <Class>Impl::configure()"),
       and the skeleton's body lines (body) -->
  <xsl:function name="fp:ros-hooks" as="map(*)*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="user" as="xs:string" select="$node/r:realizing-class/@name"/>
    <xsl:variable name="lifecycle" as="xs:string+"
        select="'lifecycle (docs/profile.md): configure() and start() as the node comes up (false: it',
                'fails), update() each period (data-driven: each message), stop() and cleanup() as it ends'"/>
    <xsl:sequence select="
        $node/r:hook ! (let $bool := @name = ('configure', 'start') return map {
          'group': $lifecycle, 'decl': (if ($bool) then 'bool ' else 'void ') || @name || '()',
          'head': (if ($bool) then 'bool ' else 'void ') || $user || '::' || @name || '()',
          'body': if ($bool) then '  return true;' else () }),
        $node/r:port[@direction eq 'in'] ! map {
          'group': 'input ports: the node hands each datum it receives, before update()',
          'decl': 'void ' || @accessor || '(const ' || r:message/@cpp-type || ' &amp; value)',
          'head': 'void ' || $user || '::' || @accessor || '(const ' || r:message/@cpp-type || ' &amp; /*value*/)',
          'body': '  // port ' || @name || ' (' || @interface || '::' || @datum || ')' },
        $node/r:port[@direction eq 'out'] ! map {
          'group': 'output ports: the node publishes what these return, after update()',
          'decl': r:message/@cpp-type || ' ' || @accessor || '() const',
          'head': r:message/@cpp-type || ' ' || $user || '::' || @accessor || '() const',
          'body': ('  // port ' || @name || ' (' || @interface || '::' || @datum || ')', '  return ' || r:message/@sample || ';') },
        $node/r:service[fp:is-own-service(.)] ! map {
          'group': 'services (~name, srv/' || @srv || '.srv): the node calls the operation for each request',
          'decl': fp:own-signature(., '', true()),
          'head': fp:own-signature(., $user || '::', true()),
          'body': (r:argument ! ('  (void)' || @name || ';'), r:result ! ('  return ' || r:message/@sample || ';')) },
        $node/r:service[not(fp:is-own-service(.))] ! (let $result := if (xs:boolean(@returns-bool)) then 'bool ' else 'void ' return map {
          'group': 'services (~name, std_srvs): the node calls the operation for each request',
          'decl': $result || @name || '(' || (if (@srv eq 'std_srvs/SetBool') then 'bool data' else '') || ')',
          'head': $result || $user || '::' || @name || '(' || (if (@srv eq 'std_srvs/SetBool') then 'bool data' else '') || ')',
          'body': (if (@srv eq 'std_srvs/SetBool') then '  (void)data;' else (), if (xs:boolean(@returns-bool)) then '  return true;' else ()) })"/>
  </xsl:function>

  <!-- the declarations of $hooks, $before and $after each, in their
       groups: a comment opens each, an empty line parts two -->
  <xsl:function name="fp:hook-declarations" as="xs:string*">
    <xsl:param name="hooks" as="map(*)*"/>
    <xsl:param name="before" as="xs:string"/>
    <xsl:param name="after" as="xs:string"/>
    <xsl:sequence select="for $i in 1 to count($hooks) return (
        if ($i eq 1 or $hooks[$i]?group[1] ne $hooks[$i - 1]?group[1])
        then ((if ($i gt 1) then '' else ()), $hooks[$i]?group ! ('  // ' || .)) else (),
        $before || $hooks[$i]?decl || $after)"/>
  </xsl:function>

  <!-- the user's source: each hook, its body a skeleton -->
  <xsl:function name="fp:ros-user-definitions" as="xs:string*">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:for-each select="fp:ros-hooks($node)">
      <xsl:sequence select="if (position() gt 1) then '' else (), fp:definition(?head, ?body)"/>
    </xsl:for-each>
  </xsl:function>

  <!-- include/<pkg>/<Class>Base.hpp: the hooks, pure virtual, and the
       parameters' members -->
  <xsl:function name="fp:ros-base-header" as="xs:string">
    <xsl:param name="node" as="element(r:node)"/>
    <xsl:variable name="class" as="xs:string" select="$node/@generated-class"/>
    <xsl:variable name="user" as="xs:string" select="$node/r:realizing-class/@name"/>
    <xsl:variable name="guard" as="xs:string" select="fp:guard($node/@namespace, $class)"/>
    <xsl:variable name="hooks" as="map(*)*" select="fp:ros-hooks($node)"/>
    <xsl:variable name="types" as="element()*" select="$node/../r:types/*[@xmi-id = ($node//r:message/@type, $node/r:member/@type)]"/>
    <xsl:variable name="clients" as="element(r:service-client)*" select="$node/r:service-client[xs:boolean(@forward)]"/>
    <xsl:sequence select="fp:lines((
        fp:banner('// ', $fp:user-xsl, fp:what($node), false()),
        concat('#ifndef ', $guard),
        concat('#define ', $guard),
        '',
        '#include &lt;string&gt;',
        if (some $t in ($node//r:message/@cpp-type, $node/r:member/@cpp-type) satisfies contains($t, 'std::vector'))
        then '#include &lt;vector&gt;' else (),
        $types ! concat('#include &lt;', @header, '&gt;'),
        (: a datum that is a message of its own (a ROS library's, a type-map entry's): its header :)
        distinct-values($node//r:message[@generated eq 'false'][@field eq '']/@msg
                        ! concat('#include &lt;', fp:message-header(., $node/..), '&gt;')),
        '',
        concat('namespace ', $node/@namespace), '{',
        '',
        '/**',
        concat(' * ', fp:doc-of($node, concat('The code of component ', $node/@name, '.'))),
        concat(' * Generated base: your ', $user, ' (include/', $node/@namespace, '/', $user, '.hpp, written once)'),
        concat(' * derives from it and implements its hooks; node ', $node/@class, ' derives from'),
        concat(' * ', $user, ' and calls them. A hook the model no longer has is gone from here,'),
        ' * so its override no longer compiles; a new one must be implemented.',
        ' */',
        concat('class ', $class),
        '{',
        'public:',
        concat('  virtual ~', $class, '() = default;'),
        '',
        'protected:',
        fp:hook-declarations($hooks, '  virtual ', ' = 0;'),
        if ($clients)
        then ('', concat('  // required interfaces (seed 003): node ', $node/@class, ' implements them, calling the provider''s service'),
              $clients ! concat('  virtual ', fp:client-method(., ''), ' = 0;'))
        else (),
        if ($node/r:member)
        then ('', '  // parameters (R4): the node sets them from its parameters before configure()',
              $node/r:member ! concat('  ', @cpp-type, ' ', @name, (if (@init ne '') then ' = ' || @init else ''), ';'))
        else (),
        '};',
        '',
        concat('}  // namespace ', $node/@namespace),
        '',
        concat('#endif  // ', $guard)))"/>
  </xsl:function>
</xsl:stylesheet>
